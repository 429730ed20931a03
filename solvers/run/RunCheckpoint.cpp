#include "solvers/run/RunCheckpoint.hpp"

#include <cstdio>

#include <Teuchos_CommHelpers.hpp>

#include "assembly/ModelEvaluator.hpp"
#include "model/MuscleHistory.hpp"
#include "solvers/incompressibility/UzawaLoop.hpp"

#include "io/deck/DeckError.hpp"
#include "io/output/CheckpointStore.hpp"
#include "io/output/OutputError.hpp"
#include "solvers/parameters/RunConfiguration.hpp"
#include "solvers/run/CheckpointContents.hpp"
#include "solvers/run/RunSetup.hpp"

namespace glossa::solvers {

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
  int failed = error.empty() ? 0 : 1, anyFailed = 0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, failed, Teuchos::outArg(anyFailed));
  if (anyFailed) throw io::OutputError(error.empty() ? "another rank could not write its checkpoint part" : error);
  if (comm_->getRank() == 0) store_->publish(step);
  comm_->barrier();
  written_ = step;
}

std::unique_ptr<Restart> RunCheckpoint::read(const std::filesystem::path &dir, const Teuchos::Comm<int> &comm,
                                             const std::string &listing, int controlGroups) {
  const io::CheckpointStore store(dir);
  const std::optional<int> step = store.latestStep();
  if (!step)
    throw io::DeckError("--restart " + dir.string() + ": no checkpoint there (" + (store.directory() / "latest").string() +
                        " is missing); a run writes one every Output/checkpoint every steps and when a signal stops it");
  auto restart = std::make_unique<Restart>();
  restart->step = *step;
  restart->part = store.readPart(*step, comm.getRank());
  restart->run = (comm.getRank() == 0 ? restart->part : store.readPart(*step, 0)).at("run");
  const nlohmann::json &run = restart->run;
  const std::string difference = firstListingDifference(run.at("deck").get<std::string>(), listing);
  if (!difference.empty())
    throw io::DeckError("--restart " + dir.string() + ": the deck is not the one the run was started with (" + difference +
                        "); a restart continues the same run, with the same deck and --set values");
  if (run.at("ranks").get<int>() != comm.getSize() || run.at("control_groups").get<int>() != controlGroups)
    throw io::DeckError("--restart " + dir.string() + ": the run was made on " + std::to_string(run.at("ranks").get<int>()) +
                        " rank(s) in " + std::to_string(run.at("control_groups").get<int>()) +
                        " control group(s); restart it on as many (its checkpoint is split by rank)");
  restart->outputs = outputMarkFromJson(run.at("outputs"));
  return restart;
}

void writeCheckpoint(RunParts &run) {
  nlohmann::json part, state;
  run.stepper->save(part, state);
  part["muscle"] = toJson(run.history->snapshot());
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
  run.stepper->restore(restart.part, restart.run);
  run.history->restore(muscleSnapshotFromJson(restart.part.at("muscle")));
  if (run.watch) run.watch->restore(restart.run);
  run.uzawa->restorePenaltyRatios(restart.run.at("penalty_ratios").get<std::vector<double>>());
  if (run.controlled) run.controlled->restore(restart.run);
  const int step = run.stepper->stepNumber();
  const double t = run.stepper->time();
  run.report->restored(restart.run.at("summary"), step, t);
  run.checkpoints->restored(step);
  if (run.talk)
    std::printf("glossa: restarting after step %d (t = %.6g s) from %s\n", step, t, run.checkpoints->directory().c_str());
  run.report->write(assemblyCounters(*run.model));
}

} // namespace glossa::solvers
