#pragma once
// The Simulation (doc/developing.md): from a validated deck it builds the scene, the distributed
// assembly, the linear and nonlinear solvers and the Uzawa loop, then steps through time,
// committing each converged step (displacement and multipliers) and rolling back a failed one,
// and writes results as it goes so a run stopped at any point leaves readable files. A
// controlled deck's steps are searched by a ControlDriver, to which the simulation is the plant.

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include "io/deck/Deck.hpp"
#include "solvers/incompressibility/MultiplierPredictor.hpp"
#include "solvers/parameters/IncompressibilityParameters.hpp"
#include "solvers/parameters/LinearSolverParameters.hpp"
#include "solvers/parameters/NewtonParameters.hpp"
#include "solvers/parameters/OutputParameters.hpp"
#include "solvers/parameters/TimeParameters.hpp"

namespace glossa::assembly {
class Assembler;
class ModelEvaluator;
class ResultEvaluator;
} // namespace glossa::assembly
namespace glossa::io {
class CheckpointStore;
class KeyedCsvWriter;
class SummaryWriter;
} // namespace glossa::io
namespace glossa::materials {
class VolumetricEnergy;
}
namespace glossa::model {
class MuscleHistory;
struct Scene;
struct SymmetryPlane;
}

namespace glossa::solvers {

class CommControlGroups;
struct ArcLengthSettings;
class ControlDriver;
class LimitPointMonitor;
class NewtonSolver;
class StepRecorder;
class StepSizeController;
class UzawaLoop;
struct ControlSetup;
struct OutputMark;

// Parameters of the sections the solver side owns ("Time", "Incompressibility",
// "Nonlinear solver", "Linear solver", "Output"), to be merged into the deck schema.
void declareSolverParameters(Teuchos::ParameterList &schema);

struct RunOptions {
  std::filesystem::path outputDirectory; // empty: the deck's Output/directory
  bool quiet = false;   // nothing but failures on the console
  bool verbose = false; // every Newton and Uzawa iteration and the controller's detail, not only a line per step
  // The ranks split into this many groups, each solving GA candidates on its own
  // sub-communicator (issue 5); must divide the rank count. 1: every rank solves every candidate.
  int controlGroups = 1;
  // If set, receives the last converged displacement of every node (3 per node, by mesh node),
  // on every rank (glossa zero-strain).
  std::vector<double> *finalDisplacement = nullptr;
  // glossa run --restart DIR: continue the run whose output directory is DIR from its latest
  // checkpoint (the deck must be the one it was started with); empty: a new run.
  std::filesystem::path restartDirectory = {};
  // If set, changes the scene built from the deck before anything else is set up (glossa
  // zero-strain: the reference positions of an iterate, gravity reversed), so that a command
  // driving runs needs no rewritten deck or intermediate file. The deck's checks have run.
  std::function<void(model::Scene &)> adjustScene = {};
};

class Simulation {
public:
  // Builds everything and records the initial state (t = 0) and the summary so far. Collective.
  // Throws io::DeckError for deck problems found while building the scene or the controller.
  Simulation(const io::Deck &deck, const Teuchos::RCP<const Teuchos::Comm<int>> &comm, const RunOptions &options);
  ~Simulation();
  Simulation(const Simulation &) = delete;
  Simulation &operator=(const Simulation &) = delete;

  double time() const { return t_; } // of the committed state
  bool finished() const;              // the committed state is at the end time

  // Attempts the next step (of the step-size controller's size) from the committed state into
  // the trial state; a controlled deck's step searches the inputs first. Nothing is committed,
  // so the committed state stays intact if it fails. Returns whether it converged. Collective.
  // With the linear predictor an attempt that fails from the extrapolated state is made once
  // more, at the same step size, from the committed state before the step is cut back.
  bool attemptStep();
  // One attempt of the step of size dt, from the committed state or its extrapolation.
  bool attemptStepFrom(double dt, bool extrapolated);
  // The trial state of a converged attempt becomes the committed one, is recorded (traces,
  // fields, the summary's step), and the muscle history is committed. Collective.
  void commitTrial();
  // After a failed attempt: the step size is cut back for the next attempt; false if it would
  // fall below the minimum (the run stops, with the reason in the summary).
  bool rollBack();
  // Steps to the end time (or the first failure below the minimum step size), then writes the
  // final summary and returns it. Collective.
  nlohmann::json run();

private:
  struct StepState; // a displacement and its element multipliers
  struct Attempt;   // one step solve's outcome
  struct Trial;     // the step being attempted
  class CandidatePlant;

  // The constructor's parts: the solvers on the control group's communicator, and the
  // summary's description of the run. `physicalVolumetric`: each tissue's volumetric law.
  void buildSolvers(const io::Deck &deck, const std::vector<materials::VolumetricEnergy> &physicalVolumetric);
  void describeRun(const io::Deck &deck, const std::vector<materials::VolumetricEnergy> &physicalVolumetric);
  void warnIgnoredIterativeSettings(const io::Deck &deck, long long unknowns);
  // One step solve from the committed state to `time` into `state` (the committed state on
  // entry); the muscle history's trial values are this step's. `quiet`: no per-iteration output
  // (a controller's candidates).
  Attempt solveStep(double time, double dt, StepState &state, bool quiet);
  // The limit-point check of a converged trial (LimitPointMonitor): its stiffness along the step,
  // and the trial refused when that is negative.
  void checkPathStiffness(Trial &trial);
  // A converged state in which material has crossed a symmetry plane is refused (model/SymmetryPlanes.hpp). Collective.
  void refuseInsideOut(const StepState &state, Attempt &attempt) const;
  // The controller, its plant and controls.csv (resumed from `resume` on a restart).
  void setUpController(const OutputMark *resume);
  void applyControlInputs(const std::vector<double> &inputs);
  void controlledStep(Trial &trial);
  // The control points' displacement (one column per point), gathered from every rank.
  Eigen::Matrix3Xd controlPointDisplacement(const StepState &state) const;
  void record(const Trial &trial);
  nlohmann::json controlJson(const Trial &trial);
  void writeSummary();
  // The committed state to <output>/checkpoint (io::CheckpointStore), unless this step has one. Collective.
  void writeCheckpoint();
  nlohmann::json runState(); // rank 0's part of a checkpoint
  // A restart: the latest checkpoint's state (every rank's part and rank 0's run part).
  struct Restart;
  std::unique_ptr<Restart> readRestart(const io::Deck &deck, const std::filesystem::path &dir) const;
  void restoreState(const Restart &restart);
  void finish();
  // Along the path by arc-length continuation (ArcLengthContinuation) from the committed state to
  // its end, each converged point committed and recorded as a step: the whole run (Time/path
  // following = arc length) or its rest once load control has located a limit point (at a limit
  // point = follow).
  void followArcLength();
  // A stop signal reached some rank: the run ends here, with the reason (every rank). Collective.
  bool stopRequested();
  // On the stop-signal watcher thread (rank 0): summary.json says at once why the run ends.
  void writeInterruptedSummary(int signal);

  std::chrono::steady_clock::time_point start_;
  double setupAtStart_, solveAtStart_; // NOX's timers when the run began
  std::string deckFile_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  RunOptions options_;
  bool root_, talk_;
  bool detail_ = false; // talk_ and --verbose: the per-iteration lines
  std::chrono::steady_clock::time_point stepsStart_; // after set-up: the time per simulated second
  double stepsStartTime_ = 0.0; // the simulated time then (a restart's)
  std::string controlLine_; // the last control step's summary, for its step's line

  // The deck's solver-side sections, parsed once (solvers/parameters).
  TimeParameters time_;
  IncompressibilityParameters incompressibility_;
  NewtonParameters newtonParameters_;
  LinearSolverParameters linear_;
  ReuseScope keptScope_ = ReuseScope::newtonSolve; // how long the Newton solver keeps its linear solver
  OutputParameters output_;
  bool controlled_ = false; // Control/type is not none

  std::unique_ptr<StepSizeController> steps_;
  // Arc-length continuation: its settings when the deck may use it (Time/path following = arc
  // length, or at a limit point = follow), whether the run is on the path now, and where it began.
  std::unique_ptr<ArcLengthSettings> arcLength_;
  bool onPath_ = false;
  bool switchToPath_ = false; // load control located a limit point: follow the path from there
  struct {
    double time = 0.0;
    int step = 0;
  } pathStart_;
  // The fields' time in results.xdmf on the path, where t may fall: the path's start plus the
  // nominal step per step along it (ParaView needs increasing times); load control: t itself.
  std::optional<double> fieldsStamp() const;
  // Time/at a limit point = stop (not with the mixed method): the stiffness along each step.
  std::unique_ptr<LimitPointMonitor> limit_;
  double lengthScale_ = 0.0;  // the largest |X| of the mesh
  std::vector<model::SymmetryPlane> planes_; // the inside-out check (model/SymmetryPlanes.hpp)
  bool softeningSaid_ = false; // the note that the path has softened, once
  std::unique_ptr<model::Scene> scene_;
  std::unique_ptr<CommControlGroups> groups_;
  // The activation and contractile stretches of the local elements: begun, updated and committed
  // here, read by the assembler (declared first, so it outlives it).
  std::unique_ptr<model::MuscleHistory> muscleHistory_;
  Teuchos::RCP<assembly::Assembler> assembler_;
  std::unique_ptr<const assembly::ResultEvaluator> results_; // of *assembler_ (declared after it)
  Teuchos::RCP<assembly::ModelEvaluator> model_;
  std::unique_ptr<NewtonSolver> newton_;
  std::unique_ptr<UzawaLoop> uzawa_;
  std::filesystem::path dir_;
  std::unique_ptr<StepRecorder> recorder_;
  int every_ = 1;
  std::unique_ptr<io::SummaryWriter> summary_;
  std::unique_ptr<io::CheckpointStore> checkpoints_;
  int checkpointEvery_ = 0;  // Output/checkpoint every (0: never)
  int checkpointedStep_ = -1; // the step of the latest checkpoint written
  std::string deckListing_;       // the validated deck, a parameter a line: a restart must be given the same
  nlohmann::json doc_;
  // summary_ and interruptedBy_, shared with the signal watcher; held over a commit's whole
  // output so that an interrupted summary.json never lags a step behind traces.csv.
  std::recursive_mutex summaryMutex_;
  int interruptedBy_ = 0;   // the stop signal, once received
  int stoppedBy_ = 0;       // the signal the run loop stopped for (every rank)

  std::unique_ptr<StepState> committed_;
  // Time/predictor = linear extrapolation: the committed state before the last one and the step
  // between them, and the state every solve of the step being attempted starts from.
  bool extrapolate_ = false;
  std::unique_ptr<StepState> previous_, stepStart_;
  double previousDt_ = 0.0;
  MultiplierPredictor multiplierPredictor_; // augmented Lagrangian: where a step's multipliers start
  std::vector<double> committedStretch_; // every group's mean fibre stretch (pruning)
  double t_ = 0.0;
  int stepNumber_ = 0;
  bool converged_ = true;
  std::string failure_;
  std::unique_ptr<Trial> trial_;

  std::unique_ptr<ControlSetup> control_;
  std::unique_ptr<io::KeyedCsvWriter> controls_;
  std::unique_ptr<CandidatePlant> plant_;
  std::unique_ptr<ControlDriver> driver_;
};

// Runs the deck; returns the summary that was written to summary.json. Collective.
// Throws io::DeckError for deck problems found while building the scene.
nlohmann::json runSimulation(const io::Deck &deck, const Teuchos::RCP<const Teuchos::Comm<int>> &comm,
                             const RunOptions &options);

} // namespace glossa::solvers
