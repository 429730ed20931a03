#pragma once
// The run's checkpoints (glossa run --restart): each rank's part of the committed state written
// to <output>/checkpoint and published once every part is on disk (io::CheckpointStore), and a
// restart's read with its checks that the deck, the ranks and the control groups are the run's,
// that every part is as written (its CRC) and that its values are ones this run could have
// written (CheckpointSanity). What goes into a part is each run component's own
// (LoadStepper::save, ...).

#include <filesystem>
#include <memory>

#include <nlohmann/json.hpp>
#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "solvers/run/CheckpointSanity.hpp"
#include "solvers/run/StepRecorder.hpp"

namespace glossa::io {
class CheckpointStore;
}

namespace glossa::solvers {

// A restart's: the latest checkpoint's state.
struct Restart {
  int step = 0;
  nlohmann::json run;  // rank 0's part: the scalars, the monitors' and controller's state, the summary, the files' lengths
  nlohmann::json part; // this rank's: displacement, multipliers, muscle history
  OutputMark outputs;
  std::filesystem::path partFile; // this rank's part, named when it cannot be restored
};

class RunCheckpoint {
public:
  // `every`: Output/checkpoint every (0: never).
  RunCheckpoint(const std::filesystem::path &dir, Teuchos::RCP<const Teuchos::Comm<int>> comm, int every);
  ~RunCheckpoint();

  // Whether a step's commit writes one.
  bool due(int step) const { return every_ > 0 && step % every_ == 0; }
  bool enabled() const { return every_ > 0; }
  // Writes this rank's part of step `step` (unless that step has one) and publishes it once
  // every rank's is on disk; a rank that cannot write stops them all (io::OutputError). Collective.
  void write(int step, const nlohmann::json &part);
  // A restart read from it counts as written.
  void restored(int step) { written_ = step; }
  const std::filesystem::path &directory() const;

  // The latest checkpoint in `dir`, on every rank or on none: io::CheckpointError (an
  // io::DeckError: exit 2) naming the file and what is wrong if there is none, if `listing` is
  // not the run's deck, if the ranks or control groups differ, if a part is damaged, cut short
  // or missing, or if a value does not fit `shape` (its step and directory are filled in here).
  // Collective: every rank refuses alike, with the message of the first rank that found a fault.
  static std::unique_ptr<Restart> read(const std::filesystem::path &dir, const Teuchos::Comm<int> &comm,
                                       const std::string &listing, int controlGroups, CheckpointShape shape);

private:
  std::unique_ptr<io::CheckpointStore> store_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  int every_;
  int written_ = -1; // the step of the latest checkpoint written
};

struct RunParts;

// The committed state of every part of a run (the load stepper's states, the muscle history, the
// monitors', the Uzawa loop's and the controller's state, where the files had got, the summary)
// checkpointed as this rank's part, unless this step has one. Collective.
void writeCheckpoint(RunParts &run);
// What this run's state holds on this rank, for RunCheckpoint::read's checks.
CheckpointShape checkpointShape(const RunParts &run);
// A restart: every part back to the checkpoint's state, the summary told of the restart. A part
// that still refuses its state is an io::CheckpointError on every rank. Collective.
void restoreRun(RunParts &run, const Restart &restart);

} // namespace glossa::solvers
