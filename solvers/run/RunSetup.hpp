#pragma once
// A run's set-up: from a validated deck, the scene, the control groups and controller set-up,
// the distributed assembly, the model evaluator with its linear solver, Newton, the Uzawa loop,
// and the run's parts around them (step solver, path watch, load stepper, recorder, checkpoint,
// report, controlled steps), each handed what it needs. The Simulation drives them.

#include <memory>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "io/deck/Deck.hpp"
#include "io/output/DirectoryLock.hpp"
#include "solvers/incompressibility/Augmentation.hpp"
#include "solvers/linear/LinearSolverFactory.hpp"
#include "solvers/parameters/ControlSection.hpp"
#include "solvers/parameters/RunConfiguration.hpp"
#include "solvers/run/ControlledSteps.hpp"
#include "solvers/run/Inertia.hpp"
#include "solvers/run/LoadStepper.hpp"
#include "solvers/run/PathWatch.hpp"
#include "solvers/run/PcritSearch.hpp"
#include "solvers/run/RunCheckpoint.hpp"
#include "solvers/run/RunOptions.hpp"
#include "solvers/run/RunReport.hpp"
#include "solvers/run/StepRecorder.hpp"
#include "solvers/run/StepSolver.hpp"
#include "solvers/stepping/ArcLengthContinuation.hpp"

namespace glossa::assembly {
class Assembler;
class ModelEvaluator;
} // namespace glossa::assembly
namespace glossa::model {
class MuscleHistory;
struct Scene;
} // namespace glossa::model

namespace glossa::solvers {

class AirflowCoupling;
class CommControlGroups;
class NewtonSolver;
class UzawaLoop;

// Declared in the order they are built; each outlives what is built after it.
struct RunParts {
  RunConfiguration config;
  RunOptions options;
  Teuchos::RCP<const Teuchos::Comm<int>> comm;
  bool root = false, talk = false, detail = false; // detail: --verbose's per-iteration lines
  std::unique_ptr<io::DirectoryLock> outputLock; // rank 0's, for the run's life (released last)
  std::unique_ptr<const model::Scene> scene; // as built from the deck, never changed after
  std::shared_ptr<const model::AirwayOutput> airway; // the deck's Airway section; null without one
  std::unique_ptr<PcritSearch> pcrit; // the airway's closing-pressure search; null without one
  std::unique_ptr<AirflowCoupling> airflow; // the airflow coupled to every solve; null without one
  // Each tissue's kappa_AL, rule and tangent law: raised by the Uzawa loop, read by the assembly.
  std::unique_ptr<Augmentation> augmentation;
  std::unique_ptr<CommControlGroups> groups;
  ControlSetup control;
  std::unique_ptr<model::MuscleHistory> history;
  Teuchos::RCP<assembly::Assembler> assembler;
  Teuchos::RCP<assembly::ModelEvaluator> model;
  LinearSolverPlan linearPlan;
  std::unique_ptr<NewtonSolver> newton;
  std::unique_ptr<UzawaLoop> uzawa;
  std::unique_ptr<StepSolver> solver;
  std::unique_ptr<PathWatch> watch;              // load control with a limit-point check; else null
  std::unique_ptr<ArcLengthSettings> arcLength;  // a deck that may follow the path; else null
  std::unique_ptr<RunReport> report;
  std::unique_ptr<Restart> restart;              // --restart's checkpoint; else null
  std::unique_ptr<RunCheckpoint> checkpoints;
  std::unique_ptr<StepRecorder> recorder;
  std::unique_ptr<LoadStepper> stepper;
  std::unique_ptr<Inertia> inertia;              // Time/analysis = dynamic; else null
  std::unique_ptr<ControlledSteps> controlled;   // a controlled deck's; else null

  StepSolverParts stepSolverParts() const;
  ~RunParts();
};

// Builds every part; the output directory is prepared (or, on a restart, its checkpoint read)
// once the deck's checks have passed. Collective. Throws io::DeckError for deck problems.
// `config`: the deck's solver sections, parsed once (parseRunConfiguration).
std::unique_ptr<RunParts> setUpRun(const io::Deck &deck, const RunConfiguration &config,
                                   const Teuchos::RCP<const Teuchos::Comm<int>> &comm, const RunOptions &options);

} // namespace glossa::solvers
