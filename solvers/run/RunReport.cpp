#include "solvers/run/RunReport.hpp"

#include <cmath>
#include <cstdio>
#include <sys/resource.h>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include "assembly/ModelEvaluator.hpp"
#include "assembly/TimeSplit.hpp"
#include "io/output/OutputError.hpp"
#include "io/output/SummaryWriter.hpp"
#include "solvers/linear/DirectFactorStatistics.hpp"
#include "solvers/run/StopSignals.hpp"

namespace glossa::solvers {

namespace {
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Seconds a Trilinos timer has accumulated (0 if it does not exist yet).
double timerSeconds(const std::string &name) {
  const auto timer = Teuchos::TimeMonitor::lookupCounter(name);
  return timer.is_null() ? 0.0 : timer->totalElapsedTime();
}

double peakMemoryMegabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// "interrupted by SIGTERM after step 12 (t = 3.75)": the reason the summary and the log give.
std::string interruption(int signal, std::size_t steps, double time) {
  return std::string("interrupted by ") + signalName(signal) + " after step " + std::to_string(steps) + " (t = " +
         std::to_string(time) + ")";
}

// A summary (as last written) marked as ended by `signal` after its last step; `cut`: the next
// step's output was under way (RunReport::interrupted).
void markInterrupted(nlohmann::json &summary, int signal, bool cut = false) {
  const std::size_t steps = summary.contains("steps") ? summary["steps"].size() : 0;
  const double time = steps > 0 ? summary["steps"].back().value("time", 0.0) : 0.0;
  summary["running"] = false;
  summary["converged"] = false;
  summary["interrupted"] = signalName(signal);
  summary["failure"] = interruption(signal, steps, time) +
                       (cut ? " while the next step was being written; the files hold the steps up to there, and some "
                              "may hold that next step too"
                            : "; the files hold the steps up to there");
  if (cut) summary["interrupted_while_writing"] = true;
}

// How long the signal watcher waits for a commit's output. Open MPI's mpiexec kills the ranks a
// second after it forwards a signal (odls_base_sigkill_timeout): the summary must be on disk by
// then, even when the disk is so slow that one fsync takes most of that second.
constexpr std::chrono::milliseconds kOutputWait{400};
} // namespace

std::string readableDuration(double seconds) {
  char text[64];
  const long s = std::lround(std::max(seconds, 0.0));
  if (s < 60) std::snprintf(text, sizeof text, "%ld s", s);
  else if (s < 3600) std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  else std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  return text;
}

void prepareOutputDirectory(const std::filesystem::path &dir) {
  std::filesystem::create_directories(dir);
  std::filesystem::remove_all(dir / "checkpoint"); // an earlier run's: --restart must not continue it
  std::filesystem::remove_all(dir / "results_steps");
  for (const char *file : {"results.xdmf", "results.h5", "traces.csv", "reactions.csv", "resultants.csv",
                           "volumes.csv", "activation.csv", "controls.csv", "summary.json"})
    std::filesystem::remove(dir / file);
}

RunReport::RunReport(Teuchos::RCP<const Teuchos::Comm<int>> comm, bool root, bool talk)
    : comm_(std::move(comm)), root_(root), talk_(talk), start_(Clock::now()), stepsStart_(start_),
      setupAtStart_(timerSeconds("NOX Total Preconditioner Construction")),
      solveAtStart_(timerSeconds("NOX Total Linear Solve")), partSecondsAtStart_(assembly::kTimedParts),
      partCallsAtStart_(assembly::kTimedParts) {
  for (std::size_t k = 0; k < partSecondsAtStart_.size(); ++k) {
    const auto timer = assembly::partTimer(static_cast<assembly::TimedPart>(k));
    partSecondsAtStart_[k] = timer->totalElapsedTime();
    partCallsAtStart_[k] = timer->numCalls();
  }
}

RunReport::~RunReport() {
  if (root_) onStopSignal({});
}

void RunReport::warn(const std::string &text) {
  doc_["warnings"].push_back(text);
  if (root_) std::fprintf(stderr, "glossa: warning: %s\n", text.c_str());
}

AssemblyCounters assemblyCounters(const assembly::ModelEvaluator &model) {
  const assembly::ElementPartCounts parts = model.elementPartCounts();
  return {model.assemblySeconds(), model.residualEvaluations(), model.tangentEvaluations(),
          model.tangentsFromResidualPass(), model.residualOnlyPasses(), parts.reused, parts.evaluated};
}

void RunReport::write(const AssemblyCounters &counters) {
  doc_["wall_seconds"] = since(start_);
  doc_["assembly_seconds"] = counters.assemblySeconds;
  // Element passes NOX asked for: residuals (each also assembles the tangent where it can), the
  // tangents among them, and the tangent requests the residual pass had already served.
  doc_["residual_evaluations"] = counters.residualEvaluations;
  doc_["tangent_evaluations"] = counters.tangentEvaluations;
  doc_["tangents_from_residual_pass"] = counters.tangentsFromResidualPass;
  doc_["residual_only_passes"] = counters.residualOnlyPasses;
  // Element evaluations on this rank: finished from the displacement part an earlier pass at the
  // same state kept (an Uzawa update's first pass, the history's and the output's), and evaluated.
  doc_["element_parts_reused"] = counters.elementPartsReused;
  doc_["element_parts_evaluated"] = counters.elementPartsEvaluated;
  // NOX's own timers split the linear solves into preconditioner set-up and Krylov iterations.
  doc_["preconditioner_setup_seconds"] = timerSeconds("NOX Total Preconditioner Construction") - setupAtStart_;
  doc_["linear_solve_seconds"] = timerSeconds("NOX Total Linear Solve") - solveAtStart_;
  // The parts of a Newton iteration outside the assembly, on this rank (bench/newton_profile.py).
  for (std::size_t k = 0; k < partSecondsAtStart_.size(); ++k) {
    const auto timer = assembly::partTimer(static_cast<assembly::TimedPart>(k));
    doc_["time_split"][assembly::timedPartNames()[k]] = {
        {"seconds", timer->totalElapsedTime() - partSecondsAtStart_[k]}, {"calls", timer->numCalls() - partCallsAtStart_[k]}};
  }
  // The direct solver's last factorisation: its ordering, fill and flops (doc/output.md).
  const DirectFactorStatistics &direct = lastDirectFactorisation();
  if (!direct.ordering.empty())
    doc_["direct_factors"] = {{"ordering", direct.ordering}, {"entries", direct.factorEntries}, {"flops", direct.flops}};
  double peak = peakMemoryMegabytes(), peakMax = 0.0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, peak, Teuchos::outArg(peakMax));
  doc_["peak_memory_mb_per_rank"] = peakMax;
  if (!root_) return;
  std::lock_guard<std::recursive_timed_mutex> lock(mutex_);
  nlohmann::json root = doc_;
  // The watcher wrote "interrupted" already; a step committed since keeps saying so.
  if (interruptedBy_ != 0 && !doc_.contains("interrupted")) markInterrupted(root, interruptedBy_);
  publish(std::move(root), io::Durability::synced, ".tmp");
}

bool RunReport::publish(nlohmann::json root, io::Durability durability, const std::string &suffix,
                        std::optional<unsigned long> onlyOver) {
  auto next = std::make_unique<io::SummaryWriter>(dir_ / "summary.json");
  next->root() = std::move(root);
  next->stage(suffix, durability); // the slow part (a sync), outside publishMutex_
  std::lock_guard<std::mutex> lock(publishMutex_);
  if (onlyOver && *onlyOver != publishedVersion_) {
    std::filesystem::remove(next->file().string() + suffix);
    return false;
  }
  next->publish(suffix);
  published_ = std::move(next);
  ++publishedVersion_;
  return true;
}

void RunReport::beginSteps(double t) {
  stepsStart_ = Clock::now();
  stepsStartTime_ = t;
  installStopSignalHandlers();
  if (root_) onStopSignal([this](int signal) { interrupted(signal); });
}

void RunReport::interrupted(int signal) {
  interruptedBy_ = signal; // from here the run's own summary writes say so too
  // Waiting for a commit's output keeps summary.json's last step that of traces.csv; past
  // kOutputWait the last published summary is marked at once, saying that a step was being
  // written. It is not synced: a rename is atomic against the kill, which is what comes next.
  std::unique_lock<std::recursive_timed_mutex> output(mutex_, std::defer_lock);
  const bool whole = output.try_lock_for(kOutputWait);
  try {
    while (true) {
      nlohmann::json root;
      unsigned long version = 0;
      {
        std::lock_guard<std::mutex> lock(publishMutex_);
        if (!published_) return; // nothing written yet: the run's thread writes the first summary
        root = published_->root();
        version = publishedVersion_;
      }
      if (root.contains("interrupted")) return; // the run's thread marked it already
      markInterrupted(root, signal, !whole);
      // A summary the run's thread published meanwhile may not say it: mark that one instead.
      if (publish(std::move(root), io::Durability::renamedOnly, ".interrupted.tmp", version)) return;
    }
  } catch (const std::exception &) {
    // Nothing more can be done on this thread; the main thread reports output errors.
  }
}

std::unique_lock<std::recursive_timed_mutex> RunReport::holdOutput() {
  std::unique_lock<std::recursive_timed_mutex> output(mutex_);
  if (!root_ || interruptedBy_ == 0) return output;
  // The signal came while this step was being solved: the watcher marked the summary of the step
  // before, and traces.csv is about to gain this one. Until this step's summary is published, the
  // one on disk says that a step was being written (renamed, not synced, as the watcher's).
  nlohmann::json root;
  unsigned long version = 0;
  {
    std::lock_guard<std::mutex> lock(publishMutex_);
    if (!published_ || published_->root().value("interrupted_while_writing", false)) return output;
    root = published_->root();
    version = publishedVersion_;
  }
  markInterrupted(root, interruptedBy_, true);
  publish(std::move(root), io::Durability::renamedOnly, ".interrupted.tmp", version);
  return output;
}

bool RunReport::stopRequested(int step, double t) {
  // Every rank agrees to stop at the same step boundary (a signal may reach them apart).
  int signal = stopSignal(), anySignal = 0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, signal, Teuchos::outArg(anySignal));
  if (anySignal == 0) return false;
  stoppedBy_ = anySignal;
  failure_ = interruption(anySignal, static_cast<std::size_t>(step), t);
  return true;
}

void RunReport::addStep(const StepTrial &trial, double t, bool onPath, double assemblySeconds, nlohmann::json step) {
  const UzawaResult &r = trial.attempt.uzawa;
  step["time"] = t;
  step["dt"] = trial.dt;
  step["newton_iterations"] = r.newtonIterations;
  if (!onPath) step["linear_iterations"] = r.linearIterations; // LOCA's bordered solves are not counted
  step["uzawa_iterations"] = r.solves;
  step["max_dilatation_error"] = r.dilatation.max;
  step["mean_dilatation_error"] = r.dilatation.mean;
  step["max_volume_change"] = r.dilatation.maxVolumeChange;
  step["min_corner_J"] = trial.attempt.minCornerJ;
  step["min_regular_corner_J"] = trial.attempt.minRegularCornerJ;
  step["max_turned_over_volume"] = trial.attempt.turnedOver;
  if (std::isfinite(trial.attempt.pathStiffness)) step["path_stiffness"] = trial.attempt.pathStiffness;
  if (!(trial.attempt.minCornerJ > 0.0) && talk_)
    std::printf("  note: element %lld (numbered from 0) has a corner turned over at t = %.6g (det F = %.3g there; its Gauss points are "
                "not inverted)\n", static_cast<long long>(trial.attempt.cornerElement), t, trial.attempt.minCornerJ);
  step["seconds"] = since(trial.start);
  step["assembly_seconds"] = assemblySeconds - trial.assemblyAtStart;
  nlohmann::json histories = nlohmann::json::array();
  for (const auto &n : r.newton)
    histories.push_back({{"residual_norms", n.residualNorms},
                         {"krylov", n.linearIterationsPerStep},
                         {"continues_last_solve", n.continuesLastSolve}});
  step["newton_solves"] = histories;
  doc_["steps"].push_back(step);
}

void RunReport::stepLine(int step, double t, double endTime, double dt, const UzawaResult &r, bool onPath,
                         const std::string &controlLine) const {
  if (!talk_) return;
  char volume[64];
  std::snprintf(volume, sizeof volume, "%s %.1e", penalty_ ? "volume change" : "dilatation error", r.dilatation.max);
  if (onPath) {
    std::printf("step %d  t = %.6g (load %.4g of the end time's)  newton %d  %s  [%s elapsed]\n", step, t, t / endTime,
                r.newtonIterations, volume, readableDuration(since(stepsStart_)).c_str());
    return;
  }
  char linear[64];
  if (directSolve_) std::snprintf(linear, sizeof linear, "direct solve, %d Krylov steps on the factors", r.linearIterations);
  else std::snprintf(linear, sizeof linear, "krylov %d", r.linearIterations);
  // step k/N with N from the step size now (the controller may still cut back or grow it), and
  // the time left from the wall time per simulated second so far.
  const double elapsed = since(stepsStart_);
  const long left = t < endTime ? std::lround(std::ceil((endTime - t) / dt - 1e-9)) : 0;
  const double remaining = t > stepsStartTime_ ? elapsed * (endTime - t) / (t - stepsStartTime_) : 0.0;
  // The contact points carrying pressure, over all contacts (none: no contact in the deck).
  char contact[64] = "";
  if (!r.contacts.empty()) {
    long active = 0;
    for (const auto &c : r.contacts) active += c.activePoints;
    std::snprintf(contact, sizeof contact, "  contact %ld points", active);
  }
  std::printf("step %d/%ld  t = %.6g of %.6g s  newton %d  %s  uzawa %d  %s%s%s  [%s elapsed, about %s left]\n", step,
              step + left, t, endTime, r.newtonIterations, linear, r.solves, volume, contact, controlLine.c_str(),
              readableDuration(elapsed).c_str(), readableDuration(remaining).c_str());
}

void RunReport::stepRefused(const StepTrial &trial) {
  if (talk_) std::printf("  step failed at t = %.6g: %s; cutting back\n", trial.time, trial.attempt.why.c_str());
  if (trial.attempt.insideOut.is_null()) return;
  nlohmann::json refusal = trial.attempt.insideOut;
  refusal["time"] = trial.time;
  doc_["inside_out_refusals"].push_back(refusal);
}

void RunReport::restored(const nlohmann::json &summary, int step, double t) {
  doc_ = summary;
  if (!doc_.contains("restarts")) doc_["restarts"] = nlohmann::json::array();
  doc_["restarts"].push_back({{"after_step", step}, {"time", t}});
}

void RunReport::finish(const AssemblyCounters &counters, double t, const nlohmann::json &finalDisplacement) {
  doc_["final_displacement"] = finalDisplacement;
  doc_["final_time"] = t;
  doc_["converged"] = failure_.empty();
  doc_["running"] = false;
  if (stoppedBy_ != 0) doc_["interrupted"] = signalName(stoppedBy_);
  if (!failure_.empty()) doc_["failure"] = failure_;
  write(counters);
  if (failure_.empty() && talk_) std::printf("glossa: done in %.2f s; results in %s\n", since(start_), dir_.c_str());
  // Why a run stopped goes to stderr, also with --quiet: a script must see it.
  if (!failure_.empty() && root_)
    std::fprintf(stderr, "glossa: stopped: %s; results so far in %s\n", failure_.c_str(), dir_.c_str());
}

void RunReport::recordingOutputFailure(const std::function<void()> &work) {
  try {
    work();
  } catch (const io::OutputError &e) {
    outputFailed(e.what());
    throw;
  } catch (const std::filesystem::filesystem_error &e) {
    outputFailed(e.what());
    throw;
  }
}

void RunReport::outputFailed(const std::string &what) {
  // Before the output directory is known (it could not be made) there is no summary to write.
  if (!root_ || dir_.empty()) return;
  std::lock_guard<std::recursive_timed_mutex> lock(mutex_);
  doc_["running"] = false;
  doc_["converged"] = false;
  doc_["failure"] = "an output file could not be written: " + what + "; the files hold what was written before it";
  doc_["output_failure"] = what;
  try {
    publish(doc_, io::Durability::synced, ".tmp");
  } catch (const std::exception &e) {
    const std::filesystem::path file = dir_ / "summary.json";
    std::fprintf(stderr, "glossa: error: %s could not be written either (%s)%s\n", file.c_str(), e.what(),
                 std::filesystem::exists(file) ? "; the one there is from the last step written, and says running"
                                               : "; there is none");
  }
}

} // namespace glossa::solvers
