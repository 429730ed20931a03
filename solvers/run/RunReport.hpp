#pragma once
// What a run says about itself: summary.json (the run's description, a record per committed
// step, the warnings, the timers, how it ended), the console's lines, and the stop signals
// (SIGTERM, SIGINT), on which summary.json says at once why the run ends and the run stops at
// the next step boundary on every rank.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "solvers/run/StepState.hpp"

namespace glossa::assembly {
class ModelEvaluator;
}
namespace glossa::io {
class SummaryWriter;
enum class Durability;
}

namespace glossa::solvers {

// Creates the output directory and removes an earlier run's files from it (a controlled run's
// activation.csv must not stand beside a later passive run's traces). Rank 0 only.
void prepareOutputDirectory(const std::filesystem::path &dir);

// 42 s, 3 min 05 s, 2 h 07 min: a duration as a person reads it.
std::string readableDuration(double seconds);

// The model evaluator's counters for the summary (element passes NOX asked for, assembly time).
struct AssemblyCounters {
  double assemblySeconds = 0.0;
  int residualEvaluations = 0, tangentEvaluations = 0, tangentsFromResidualPass = 0, residualOnlyPasses = 0;
  std::uint64_t elementPartsReused = 0, elementPartsEvaluated = 0;
};
AssemblyCounters assemblyCounters(const assembly::ModelEvaluator &model);

class RunReport {
public:
  // `talk`: this rank prints (rank 0, not --quiet); `root`: it writes summary.json.
  RunReport(Teuchos::RCP<const Teuchos::Comm<int>> comm, bool root, bool talk);
  ~RunReport();

  nlohmann::json &doc() { return doc_; }
  void setDirectory(const std::filesystem::path &dir) { dir_ = dir; }
  // A warning: in summary.json's warnings and on stderr (also with --quiet).
  void warn(const std::string &text);

  // Writes summary.json with the model's counters and the timers so far. Collective.
  void write(const AssemblyCounters &counters);
  // Held over a commit's whole output, so that an interrupted summary.json does not lag a step
  // behind traces.csv (unless the output outlasts kOutputWait: interrupted()).
  // Once a stop signal has come, the summary on disk is first marked as cut while this output is
  // written: mpiexec's kill may land before the step's own summary.
  std::unique_lock<std::recursive_timed_mutex> holdOutput();

  // From here a stop signal ends the run at the next step boundary; the time steps begin at t.
  void beginSteps(double t);
  // A stop signal reached some rank: every rank agrees, and the reason is recorded. Collective.
  bool stopRequested(int step, double t);
  int stoppedBy() const { return stoppedBy_; }
  const std::string &failure() const { return failure_; }
  bool converged() const { return failure_.empty(); }
  void fail(const std::string &why) { failure_ = why; }

  // What the step lines call the linear solves and the volume measure: a direct solve's Krylov
  // steps are iterations on its (possibly reused) factors, not an iterative solve's; the penalty
  // method's "error" is the volume change max |theta - 1| (UzawaLoop::dilatationError).
  void describeSolves(bool directSolve, bool penalty) {
    directSolve_ = directSolve;
    penalty_ = penalty;
  }
  // The summary's record of a committed step (its reactions and activation given), and its line.
  void addStep(const StepTrial &trial, double t, bool onPath, double assemblySeconds, nlohmann::json step);
  void stepLine(int step, double t, double endTime, double dt, const UzawaResult &r, bool onPath,
                const std::string &controlLine) const;
  // A refused trial: its line, and where it was inside out.
  void stepRefused(const StepTrial &trial);
  // A restart's summary so far, with the restart recorded.
  void restored(const nlohmann::json &summary, int step, double t);
  // The end: the final displacements, how it ended, and where the results are. Collective.
  void finish(const AssemblyCounters &counters, double t, const nlohmann::json &finalDisplacement);
  // Runs `work`; when an output file cannot be written in it (io::OutputError, a filesystem
  // error), summary.json says at once that the run ended so and names the file (`running`
  // false, `failure`, `output_failure`), or stderr says that summary.json could not be written
  // either, before the error goes on to end the run (exit status 4, on every rank). Rank 0
  // writes; a rank alone in the error ends the job (main), so nothing here is collective.
  void recordingOutputFailure(const std::function<void()> &work);

private:
  void interrupted(int signal); // on the signal watcher thread (rank 0)
  // Writes `root` as summary.json (fsync'ed when `durability` says so), unless `onlyOver` is given
  // and another summary was published since that version; returns whether it was published.
  bool publish(nlohmann::json root, io::Durability durability, const std::string &suffix,
               std::optional<unsigned long> onlyOver = std::nullopt);
  void outputFailed(const std::string &what);

  using Clock = std::chrono::steady_clock;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  bool root_, talk_;
  bool directSolve_ = false, penalty_ = false;
  Clock::time_point start_, stepsStart_;
  double stepsStartTime_ = 0.0;         // the simulated time when the steps began (a restart's)
  double setupAtStart_, solveAtStart_; // NOX's timers when the run began
  std::vector<double> partSecondsAtStart_; // the time split's timers (assembly/TimeSplit.hpp) then
  std::vector<int> partCallsAtStart_;
  std::filesystem::path dir_;
  nlohmann::json doc_;
  // The output lock: a commit's output and the summary writes on the run's thread.
  std::recursive_timed_mutex mutex_;
  // The summary last published and its version (0: none yet), shared with the signal watcher.
  // publishMutex_ is held only over a rename and a copy, never over a sync.
  std::mutex publishMutex_;
  std::unique_ptr<io::SummaryWriter> published_;
  unsigned long publishedVersion_ = 0;
  std::atomic<int> interruptedBy_{0}; // the stop signal, once received
  int stoppedBy_ = 0;     // the signal the run loop stopped for (every rank)
  std::string failure_;
};

} // namespace glossa::solvers
