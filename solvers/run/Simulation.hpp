#pragma once
// The Simulation (doc/architecture.md): the facade of a run. Its parts are set up from a
// validated deck (RunSetup); it then steps through time, each step attempted by the load
// stepper (LoadStepper) through the step solver (StepSolver) or the controller
// (ControlledSteps), checked by the path watch (PathWatch), committed and recorded
// (StepRecorder, RunReport), checkpointed (RunCheckpoint), or rolled back and cut back; past a
// located limit point the path may be followed by arc length (PathFollowing).

#include <memory>
#include <optional>

#include <nlohmann/json.hpp>
#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "io/deck/Deck.hpp"
#include "solvers/parameters/RunConfiguration.hpp"
#include "solvers/run/LoadStepper.hpp"
#include "solvers/run/RunOptions.hpp"
#include "solvers/run/RunSimulation.hpp"

namespace glossa::solvers {

struct RunParts;

class Simulation final : private StepAttempter {
public:
  // Builds everything and records the initial state (t = 0) and the summary so far. `config`:
  // the deck's solver sections, parsed once (parseRunConfiguration). Collective.
  // Throws io::DeckError for deck problems found while building the scene or the controller.
  Simulation(const io::Deck &deck, const RunConfiguration &config, const Teuchos::RCP<const Teuchos::Comm<int>> &comm,
             const RunOptions &options);
  ~Simulation() override;
  Simulation(const Simulation &) = delete;
  Simulation &operator=(const Simulation &) = delete;

  // Steps to the end time (or the first failure below the minimum step size, a located limit
  // point, a stop signal), then writes the final summary and returns it. Collective.
  nlohmann::json run();

private:
  void attempt(StepTrial &trial) override; // a step solve, or the controller's search
  void commit();   // the converged trial becomes the committed state and is recorded
  bool rollBack(); // after a failure: false if the run stops here
  void record(const StepTrial &trial);
  // The contacts of a converged step into its summary entry, and the run's gap verdict
  // (summary.json: contact).
  void recordContacts(const UzawaResult &uzawa, nlohmann::json &step);
  // A dynamic run's energies at the committed state, to energy.csv and into the step's record.
  // The flow of the committed step (a scene with airflow), and its airflow.csv row and summary.
  AirflowStep committedAirflow(const StepTrial &trial);
  void recordAirflow(const AirflowStep &airflow, nlohmann::json &step);
  void recordEnergy(nlohmann::json *step);
  void followPath(); // by arc length from the committed state to the path's end
  // The closing-pressure search (PcritSearch): whether the converged trial closes the airway (it
  // is then not committed), and, after each step, whether the run goes on (false: Pcrit is
  // bracketed, or the bisection's step fell below the minimum). Collective.
  bool trialClosesAirway();
  bool pcritGoesOn(bool closed);
  void finish();
  // The fields' time in results.xdmf on the path, where t may fall: the path's start plus the
  // nominal step per step along it (ParaView needs increasing times); load control: t itself.
  std::optional<double> fieldsStamp() const;

  std::unique_ptr<RunParts> run_;
  bool onPath_ = false;       // on an arc-length path now
  bool switchToPath_ = false; // load control located a limit point: follow the path from there
  double pathStartTime_ = 0.0;
  int pathStartStep_ = 0;
};

} // namespace glossa::solvers
