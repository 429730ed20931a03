#include "solvers/run/RunCheckpoint.hpp"

#include <algorithm>
#include <cstdio>

#include <Teuchos_CommHelpers.hpp>

#include "assembly/Assembler.hpp"
#include "assembly/ModelEvaluator.hpp"
#include "model/MuscleHistory.hpp"
#include "model/Scene.hpp"
#include "solvers/incompressibility/UzawaLoop.hpp"

#include "io/output/CheckpointError.hpp"
#include "io/output/CheckpointStore.hpp"
#include "io/output/OutputError.hpp"
#include "solvers/parameters/RunConfiguration.hpp"
#include "solvers/run/CheckpointContents.hpp"
#include "solvers/run/RunSetup.hpp"

namespace glossa::solvers {

namespace {

// Every rank's verdict, agreed: empty on every rank if no rank found a fault, else the message of
// the first rank that did, on every rank (so that all refuse alike and none waits for the others).
std::string agreedError(const Teuchos::Comm<int> &comm, const std::string &error) {
  const int mine = error.empty() ? comm.getSize() : comm.getRank();
  int first = mine;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(first));
  if (first == comm.getSize()) return {};
  int length = comm.getRank() == first ? static_cast<int>(error.size()) : 0;
  Teuchos::broadcast(comm, first, &length);
  std::string message = comm.getRank() == first ? error : std::string(static_cast<std::size_t>(length), '\0');
  if (length > 0) Teuchos::broadcast(comm, first, length, message.data());
  return message;
}

}  // namespace

RunCheckpoint::RunCheckpoint(const std::filesystem::path &dir, Teuchos::RCP<const Teuchos::Comm<int>> comm, int every)
    : store_(std::make_unique<io::CheckpointStore>(dir)), comm_(std::move(comm)), every_(every) {}

RunCheckpoint::~RunCheckpoint() = default;

const std::filesystem::path &RunCheckpoint::directory() const { return store_->directory(); }

void RunCheckpoint::write(int step, const nlohmann::json &part) {
  if (written_ == step) return;
  // Published only once every rank's part is on disk; a rank that cannot write stops them all.
  std::string error;
  try {
    store_->writePart(step, comm_->getRank(), part);
  } catch (const std::exception &e) {
    error = e.what();
  }
  // Every rank throws the failing rank's own message (the file and why): rank 0, which reports,
  // may not be the rank that failed, and the job ends before another rank's words reach stderr.
  const std::string agreed = agreedError(*comm_, error);
  if (!agreed.empty()) throw io::OutputError(agreed);
  if (comm_->getRank() == 0) store_->publish(step);
  comm_->barrier();
  written_ = step;
}

namespace {

// Runs `check` on what was read from `file`: a value that fails, or a type or key that is not
// there (a part edited so that its CRC still holds), becomes an io::CheckpointError naming the file.
template <class F> void fromFile(const std::filesystem::path &file, F &&check) {
  try {
    check();
  } catch (const io::CheckpointError &e) {
    throw io::CheckpointError("checkpoint part " + file.string() + ": " + e.what());
  } catch (const nlohmann::json::exception &e) {
    throw io::CheckpointError("checkpoint part " + file.string() + " does not hold a run's state: " + e.what());
  }
}

const char *kRemedy = "; it cannot be trusted: run the deck again without --restart, or restart from an intact copy";

std::unique_ptr<Restart> readChecked(const std::filesystem::path &dir, const Teuchos::Comm<int> &comm,
                                     const std::string &listing, int controlGroups, CheckpointShape shape) {
  const io::CheckpointStore store(dir);
  const std::optional<int> step = store.latestStep();
  if (!step)
    throw io::CheckpointError("--restart " + dir.string() + ": no checkpoint there (" + (store.directory() / "latest").string() +
                              " is missing); a run writes one every Output/checkpoint every steps and when a signal stops it");
  shape.step = *step;
  shape.outputDirectory = dir;
  auto restart = std::make_unique<Restart>();
  restart->step = *step;
  // Rank 0's part first: its run part says whether this is the run's deck and rank count before
  // a part this rank might not have is looked for.
  const std::filesystem::path runFile = store.partPath(*step, 0);
  const nlohmann::json rank0 = store.readPart(*step, 0);
  int ranks = 0, groups = 0;
  std::string deck;
  fromFile(runFile, [&] {
    restart->run = rank0.at("run");
    deck = restart->run.at("deck").get<std::string>();
    ranks = restart->run.at("ranks").get<int>();
    groups = restart->run.at("control_groups").get<int>();
  });
  const std::string difference = firstListingDifference(deck, listing);
  if (!difference.empty())
    throw io::CheckpointError("--restart " + dir.string() + ": the deck is not the one the run was started with (" +
                              difference + "); a restart continues the same run, with the same deck and --set values (" +
                              runFile.string() + " records the run's)");
  if (ranks != comm.getSize() || groups != controlGroups)
    throw io::CheckpointError("--restart " + dir.string() + ": the run was made on " + std::to_string(ranks) + " rank(s) in " +
                              std::to_string(groups) + " control group(s); restart it on as many (its checkpoint is split by rank: " +
                              runFile.string() + ")");
  fromFile(runFile, [&] {
    checkRunValues(restart->run, shape);
    restart->outputs = outputMarkFromJson(restart->run.at("outputs"));
  });
  restart->partFile = store.partPath(*step, comm.getRank());
  restart->part = comm.getRank() == 0 ? rank0 : store.readPart(*step, comm.getRank());
  fromFile(restart->partFile, [&] { checkPartValues(restart->part, restart->run.at("time").get<double>(), shape); });
  return restart;
}

} // namespace

std::unique_ptr<Restart> RunCheckpoint::read(const std::filesystem::path &dir, const Teuchos::Comm<int> &comm,
                                             const std::string &listing, int controlGroups, CheckpointShape shape) {
  std::unique_ptr<Restart> restart;
  std::string error;
  try {
    restart = readChecked(dir, comm, listing, controlGroups, std::move(shape));
  } catch (const io::CheckpointError &e) {
    error = e.what();
    // A checkpoint of another deck or rank count is intact, only not this run's.
    if (error.rfind("--restart ", 0) != 0) error = "--restart " + dir.string() + ": " + error + kRemedy;
  } catch (const std::exception &e) {
    error = "--restart " + dir.string() + ": the checkpoint cannot be read: " + e.what() + kRemedy;
  }
  const std::string agreed = agreedError(comm, error);
  if (!agreed.empty()) throw io::CheckpointError(agreed);
  return restart;
}

CheckpointShape checkpointShape(const RunParts &run) {
  CheckpointShape shape;
  const StepSizeRule &steps = run.config.time.steps;
  shape.endTime = steps.endTime;
  shape.nominalStep = std::min(steps.nominal, steps.endTime); // as the step-size controller takes it
  shape.minimumStep = steps.minimum;
  shape.displacements = run.assembler->layout().ownedMap()->getNodeNumElements();
  shape.elements = run.assembler->layout().numLocalElements();
  shape.tissues = run.uzawa->penaltyRatios().size();
  shape.dynamic = run.config.time.dynamics.dynamic();
  const model::MuscleHistory::Snapshot history = run.history->snapshot();
  shape.groups = history.alpha.size();
  shape.lambdaC = history.lambdaC.size();
  for (const auto &external : history.externalLambdaC) shape.externalLambdaC.push_back(external.size());
  for (const auto &contact : run.scene->contacts)
    shape.contactPoints.push_back(contact.state ? contact.state->snapshot().multipliers.size() : 0);
  return shape;
}

void writeCheckpoint(RunParts &run) {
  nlohmann::json part, state;
  run.stepper->save(part, state);
  part["muscle"] = toJson(run.history->snapshot());
  if (run.inertia) run.inertia->save(part);
  if (!run.scene->contacts.empty()) {
    nlohmann::json contacts = nlohmann::json::array();
    for (const auto &contact : run.scene->contacts)
      contacts.push_back(toJson(contact.state ? contact.state->snapshot() : contact::ContactState::Snapshot{}));
    part["contact"] = contacts;
  }
  if (run.root) {
    state["deck"] = run.config.listing;
    state["ranks"] = run.comm->getSize();
    state["control_groups"] = run.options.controlGroups;
    state.update(run.watch ? run.watch->state() : nlohmann::json{{"softening_said", false}});
    state["penalty_ratios"] = run.uzawa->penaltyRatios();
    OutputMark outputs = run.recorder->mark();
    if (run.controlled) {
      run.controlled->save(state);
      if (const auto bytes = run.controlled->controlsBytes()) outputs.csvBytes["controls.csv"] = *bytes;
    }
    state["outputs"] = toJson(outputs);
    state["summary"] = run.report->doc();
    part["run"] = state;
  }
  run.checkpoints->write(run.stepper->stepNumber(), part);
}

void restoreRun(RunParts &run, const Restart &restart) {
  // The values were checked on reading; a part that still refuses its state stops every rank alike.
  std::string error;
  try {
    run.stepper->restore(restart.part, restart.run);
    run.history->restore(muscleSnapshotFromJson(restart.part.at("muscle")));
    if (run.inertia) run.inertia->restore(restart.part, run.stepper->committed());
    for (std::size_t c = 0; c < run.scene->contacts.size(); ++c)
      if (run.scene->contacts[c].state)
        run.scene->contacts[c].state->restore(contactSnapshotFromJson(restart.part.at("contact").at(c)));
    if (run.watch) run.watch->restore(restart.run);
    run.uzawa->restorePenaltyRatios(restart.run.at("penalty_ratios").get<std::vector<double>>());
    if (run.controlled) run.controlled->restore(restart.run);
  } catch (const std::exception &e) {
    error = "--restart " + run.checkpoints->directory().string() + ": checkpoint part " + restart.partFile.string() +
            " cannot be restored: " + e.what() + kRemedy;
  }
  const std::string agreed = agreedError(*run.comm, error);
  if (!agreed.empty()) throw io::CheckpointError(agreed);
  const int step = run.stepper->stepNumber();
  const double t = run.stepper->time();
  run.report->restored(restart.run.at("summary"), step, t);
  run.checkpoints->restored(step);
  if (run.talk)
    std::printf("glossa: restarting after step %d (t = %.6g s) from %s\n", step, t, run.checkpoints->directory().c_str());
  run.report->write(assemblyCounters(*run.model));
}

} // namespace glossa::solvers
