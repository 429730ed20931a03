#include "solvers/run/Simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <sys/resource.h>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include "assembly/Assembler.hpp"
#include "assembly/ModelEvaluator.hpp"
#include "assembly/NullSpace.hpp"
#include "assembly/ResultEvaluator.hpp"
#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "io/deck/NameList.hpp"
#include "io/output/CheckpointStore.hpp"
#include "io/output/KeyedCsvWriter.hpp"
#include "io/output/OutputError.hpp"
#include "io/output/ResultWriter.hpp"
#include "io/output/SummaryWriter.hpp"
#include "io/output/TraceWriter.hpp"
#include "input/SceneFactory.hpp"
#include "model/SymmetryPlanes.hpp"
#include "solvers/stepping/ArcLengthContinuation.hpp"
#include "solvers/run/CheckpointContents.hpp"
#include "solvers/control/CommControlGroups.hpp"
#include "solvers/control/ControlDriver.hpp"
#include "solvers/parameters/ControlSection.hpp"
#include "assembly/MuscleResponse.hpp"
#include "solvers/control/ControlSensitivity.hpp"
#include "solvers/stepping/LimitPointMonitor.hpp"
#include "solvers/linear/LinearSolverFactory.hpp"
#include "solvers/nonlinear/NewtonSolver.hpp"
#include "solvers/stepping/PathStiffness.hpp"
#include "solvers/run/StepRecorder.hpp"
#include "solvers/run/StopSignals.hpp"
#include "solvers/linear/MixedBlockSolver.hpp"
#include "solvers/incompressibility/UzawaLoop.hpp"

namespace glossa::solvers {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// 42 s, 3 min 05 s, 2 h 07 min: a duration as a person reads it.
std::string readableDuration(double seconds) {
  char text[64];
  const long s = std::lround(std::max(seconds, 0.0));
  if (s < 60) std::snprintf(text, sizeof text, "%ld s", s);
  else if (s < 3600) std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  else std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  return text;
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

// A summary (as last written) marked as ended by `signal` after its last step.
void markInterrupted(nlohmann::json &summary, int signal) {
  const std::size_t steps = summary.contains("steps") ? summary["steps"].size() : 0;
  const double time = steps > 0 ? summary["steps"].back().value("time", 0.0) : 0.0;
  summary["running"] = false;
  summary["converged"] = false;
  summary["interrupted"] = signalName(signal);
  summary["failure"] = interruption(signal, steps, time) + "; the files hold the steps up to there";
}

// Creates the output directory and removes an earlier run's files from it (a controlled run's
// activation.csv must not stand beside a later passive run's traces). Rank 0 only.
void prepareOutputDirectory(const std::filesystem::path &dir) {
  std::filesystem::create_directories(dir);
  std::filesystem::remove_all(dir / "checkpoint"); // an earlier run's: --restart must not continue it
  std::filesystem::remove_all(dir / "results_steps");
  for (const char *file : {"results.xdmf", "results.h5", "traces.csv", "reactions.csv", "resultants.csv",
                           "volumes.csv", "activation.csv", "controls.csv", "summary.json"})
    std::filesystem::remove(dir / file);
}

// The mesh node with the largest |v| and that |v| (gathered on every rank). Collective.
struct LargestMotion {
  std::size_t node = 0;
  double norm = 0.0;
};
LargestMotion largestMotion(const assembly::ResultEvaluator &results, const assembly::Vector &v) {
  const std::vector<double> all = results.gatherDisplacement(v);
  LargestMotion best;
  double largest = -1.0;
  for (std::size_t n = 0; 3 * n + 2 < all.size(); ++n) {
    const double m = Eigen::Vector3d(all[3 * n], all[3 * n + 1], all[3 * n + 2]).squaredNorm();
    if (m > largest) largest = m, best.node = n;
  }
  best.norm = std::sqrt(std::max(largest, 0.0));
  return best;
}

// The deck as "Section/sub/name = value" lines (every default filled in, doubles to 17 digits): a
// restart must be given the same.
void listParameters(const Teuchos::ParameterList &list, const std::string &path, std::ostringstream &out) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string name = path + list.name(it);
    const Teuchos::ParameterEntry &entry = list.entry(it);
    if (entry.isList()) listParameters(Teuchos::getValue<Teuchos::ParameterList>(entry), name + "/", out);
    else out << name << " = " << entry.getAny(false) << '\n';
  }
}
std::string parameterListing(const Teuchos::ParameterList &deck) {
  std::ostringstream out;
  out.precision(17);
  listParameters(deck, "", out);
  return out.str();
}

// The first parameter where two listings differ, for the message that a restart's deck is not the run's.
std::string firstDifference(const std::string &run, const std::string &now) {
  std::istringstream a(run), b(now);
  std::string l1, l2;
  while (true) {
    const bool more1 = static_cast<bool>(std::getline(a, l1)), more2 = static_cast<bool>(std::getline(b, l2));
    if (!more1 && !more2) return "";
    if (!more1 || !more2 || l1 != l2) return "the run's " + (more1 ? l1 : "end") + ", now " + (more2 ? l2 : "end");
  }
}
} // namespace

void declareSolverParameters(Teuchos::ParameterList &schema) {
  schema.set("Time", timeParameters(), "load/time stepping");
  schema.set("Incompressibility", incompressibilityParameters(), "the incompressibility algorithm");
  schema.set("Nonlinear solver", nonlinearSolverParameters(), "Newton's method (NOX)");
  schema.set("Linear solver", linearSolverParameters(), "Krylov solver and preconditioner (Belos, MueLu, Ifpack2, Amesos2)");
  schema.set("Output", outputParameters(), "result files");
  schema.set("Control", controlParameters(), "neural control of the muscle groups (paper §6.1)");
}

namespace {
// Incompressibility/method = mixed carries the element pressures in the Newton iterate: it needs
// the mixed element, a full Newton step (the pressure increment is not line-searched), an
// iterative block solve, and no controller (its sensitivities are condensed solves).
void requireMixedCompatible(const LinearSolverParameters &linear, bool controlled,
                            const model::Scene &scene) {
  const std::string why = "Incompressibility/method = mixed needs ";
  if (scene.formulation != model::ElementFormulation::Q1P0) throw io::DeckError(why + "Material/element = Q1P0");
  if (linear.type == LinearSolverType::direct)
    throw io::DeckError(why + "Linear solver/type = iterative or auto (the block system is solved by GMRES; "
                              "auto may precondition its displacement block by a direct solve)");
  if (controlled)
    throw io::DeckError(why + "Control/type = none (the controllers' sensitivities use the condensed tangent)");
  if (scene.tissues.size() > 1)
    throw io::DeckError(why + "one tissue (its pressure state holds one volumetric law); use the augmented Lagrangian "
                              "for Material/Tissues");
}

// Time/path following = arc length makes the time an unknown of each step (ArcLengthContinuation):
// nothing else may depend on the time in a way the path cannot follow back.
// `parameter`: the Time parameter that asks for it ("path following", or "at a limit point" =
// follow, whose run may be restarted from a checkpoint written before the path began).
void requireArcLengthCompatible(const io::Deck &deck, const IncompressibilityParameters &incompressibility,
                                bool controlled, const model::Scene &scene, const RunOptions &options,
                                const std::string &parameter) {
  const std::string why = deck.where({"Time", parameter}) + ": arc-length continuation needs ";
  if (incompressibility.method != IncompressibilityMethod::penalty)
    throw io::DeckError(why + "Incompressibility/method = penalty (the augmented Lagrangian's multipliers and the "
                              "mixed method's pressures would change within a continuation step; a penalty with nu "
                              "= 0.49999 keeps the thick sphere's volume to 4e-5)");
  if (controlled) throw io::DeckError(why + "Control/type = none (a controller searches inputs at a given time)");
  if (!scene.muscles.groups.empty())
    throw io::DeckError(why + "no muscle groups (their activation is a history in time, which the path may run "
                              "backwards)");
  for (const auto &bc : scene.dirichlet) {
    bool moves = !bc.value.isZero();
    for (const auto &e : bc.expression) moves = moves || static_cast<bool>(e);
    if (moves)
      throw io::DeckError(why + "supports that prescribe no motion: Boundary conditions/" + bc.name +
                          " prescribes a displacement (drive the path by its loads)");
  }
  if (parameter == "path following" && !options.restartDirectory.empty())
    throw io::DeckError("--restart does not continue an arc-length path (its direction and step are LOCA's own "
                        "state); run it again");
}

ArcLengthSettings arcLengthSettings(const TimeParameters &time, const NewtonParameters &newton,
                                    const LinearSolverParameters &linear, const assembly::Assembler &assembler) {
  ArcLengthSettings s;
  s.endTime = time.steps.endTime;
  s.stepSize = std::min(time.steps.nominal, s.endTime);
  s.minimumStepSize = time.steps.minimum;
  s.maximumSteps = time.arcLengthSteps;
  s.stopAtDisplacement = time.stopAtDisplacement;
  s.maximumNewtonIterations = newton.maximumIterations;
  // Relative to the load at the end time: the path's loads are fractions of it.
  const double reference = assembler.externalForceNorm(s.endTime);
  s.residualTolerance = newton.residualTolerance * (reference > 0.0 ? reference : 1.0);
  s.linearTolerance = linear.tolerance;
  return s;
}
} // namespace

struct Simulation::StepState {
  StepState(const Teuchos::RCP<const assembly::Map> &map, std::size_t elements) : u(map), lambda(elements, 0.0) {}
  StepState(const StepState &from) : u(from.u, Teuchos::Copy), lambda(from.lambda) {}
  StepState &operator=(const StepState &) = delete;
  void assign(const StepState &from) {
    u.assign(from.u);
    lambda = from.lambda;
  }
  assembly::Vector u;
  std::vector<double> lambda; // Lambda_e, per local element
};

struct Simulation::Restart {
  int step = 0;
  nlohmann::json run;  // rank 0's part: the scalars, the monitors' and controller's state, the summary, the files' lengths
  nlohmann::json part; // this rank's: displacement, multipliers, muscle history
  OutputMark outputs;
};

struct Simulation::Attempt {
  UzawaResult uzawa;
  assembly::MuscleFields muscle;
  bool ok = false;
  std::string why;
  double minCornerJ = 1.0;       // the smallest corner det F of the converged state
  mesh::ElementId cornerElement = 0; // where
  double minRegularCornerJ = 1.0; // the same over regular corners (ResultEvaluator::WorstCorner)
  mesh::ElementId regularCornerElement = 0;
  double pathStiffness = std::numeric_limits<double>::quiet_NaN(); // S (LimitPointMonitor); NaN: not measured
  bool unstable = false;         // converged, but past a limit point (S <= 0)
  nlohmann::json insideOut;      // converged inside out: where (SymmetryPlanes.hpp)
};

struct Simulation::Trial {
  Trial(double time, double dt, double assemblyAtStart, const StepState &committed)
      : time(time), dt(dt), start(Clock::now()), assemblyAtStart(assemblyAtStart), state(committed) {}
  double time, dt;
  Clock::time_point start;
  double assemblyAtStart;
  StepState state; // the committed state on entry, the trial state after the attempt
  Attempt attempt;
  ControlStepResult control; // a controlled step's
};

// The simulation as the control driver's plant: every candidate is a step solve from the
// committed state into `last_`; the one the driver keeps is copied to `kept_`.
class Simulation::CandidatePlant final : public ControlPlant {
public:
  explicit CandidatePlant(Simulation &simulation)
      : sim_(simulation), last_(*simulation.committed_), kept_(*simulation.committed_) {}

  CandidateSolve solve(const std::vector<double> &inputs) override {
    sim_.applyControlInputs(inputs);
    last_.assign(*sim_.stepStart_);
    const Trial &trial = *sim_.trial_;
    Attempt a = sim_.solveStep(trial.time, trial.dt, last_, true);
    CandidateSolve out;
    out.ok = a.ok;
    out.why = a.why;
    out.statistics = std::move(a.uzawa);
    if (a.ok) out.pointDisplacement = sim_.controlPointDisplacement(last_);
    return out;
  }

  void keepLast() override { kept_.assign(last_); }

  InputSensitivity sensitivity(const std::vector<double> &inputs, const std::vector<int> &groups) override {
    const Trial &trial = *sim_.trial_;
    sim_.applyControlInputs(inputs);
    sim_.muscleHistory_->beginStep(trial.time, trial.dt);
    sim_.model_->setTime(trial.time);
    sim_.model_->setMultipliers(kept_.lambda);
    const auto s = controlPointSensitivity(*sim_.newton_, kept_.u, groups);
    return {s.dxdu, s.krylovIterations};
  }

  // [u of every node (3 per node), Lambda of every element].
  std::vector<double> packKept() const override {
    std::vector<double> state = sim_.results_->gatherDisplacement(kept_.u);
    const std::vector<double> lambdaAll = sim_.results_->gatherElementField(kept_.lambda, 1);
    state.insert(state.end(), lambdaAll.begin(), lambdaAll.end());
    return state;
  }

  void unpackKept(const std::vector<double> &state) override {
    const auto split = state.begin() + static_cast<long>(3 * sim_.scene_->mesh.numNodes());
    sim_.results_->scatterDisplacement(std::vector<double>(state.begin(), split), kept_.u);
    kept_.lambda = sim_.results_->localElementValues(std::vector<double>(split, state.end()));
  }

  // The winner's trial muscle history (activation and lambda_c at its converged state, no
  // solve), then its state, become the trial's.
  void adoptKept(Trial &trial) {
    sim_.applyControlInputs(trial.control.inputs);
    sim_.muscleHistory_->beginStep(trial.time, trial.dt);
    trial.attempt.muscle = assembly::updateMuscleHistory(*sim_.results_, kept_.u, *sim_.muscleHistory_);
    trial.state.assign(kept_);
    trial.attempt.uzawa = trial.control.solve;
    trial.attempt.ok = true;
  }

private:
  Simulation &sim_;
  StepState last_, kept_;
};

Simulation::Simulation(const io::Deck &deck, const Teuchos::RCP<const Teuchos::Comm<int>> &comm,
                       const RunOptions &options)
    : start_(Clock::now()), setupAtStart_(timerSeconds("NOX Total Preconditioner Construction")),
      solveAtStart_(timerSeconds("NOX Total Linear Solve")), deckFile_(deck.file()), comm_(comm), options_(options),
      root_(comm->getRank() == 0), talk_(root_ && !options.quiet), detail_(talk_ && options.verbose) {
  const auto &D = deck.root();
  time_ = parseTimeParameters(D.sublist("Time"));
  incompressibility_ = parseIncompressibilityParameters(D.sublist("Incompressibility"));
  newtonParameters_ = parseNewtonParameters(D.sublist("Nonlinear solver"));
  linear_ = parseLinearSolverParameters(D.sublist("Linear solver"));
  output_ = parseOutputParameters(D.sublist("Output"));
  controlled_ = controlRequested(D.sublist("Control"));
  steps_ = std::make_unique<StepSizeController>(time_.steps);
  scene_ = std::make_unique<model::Scene>(input::buildScene(deck, steps_->endTime()));
  model::Scene &scene = *scene_;
  if (options.adjustScene) options.adjustScene(scene);
  // Each tissue's law stays the physical one for the Uzawa loop; the tangent gets its kappa_t.
  std::vector<materials::VolumetricEnergy> physicalVolumetric;
  for (auto &tissue : scene.tissues) {
    physicalVolumetric.push_back(tissue.volumetric);
    tissue.volumetric = tissue.volumetric.withKappa(
        UzawaLoop::tangentKappa(incompressibility_, tissue.volumetric.kappa(), tissue.matrix->shearModulus()));
  }

  // Control groups: the world splits into G groups of equal size, each with its own copy of
  // the whole solver on a sub-communicator (every group steps the same committed state; GA
  // candidates are dealt out among the groups and the winner's state is broadcast).
  const int controlGroups = options.controlGroups;
  if (controlGroups < 1 || comm->getSize() % controlGroups != 0)
    throw io::DeckError("--control-groups " + std::to_string(controlGroups) +
                        " must be at least 1 and divide the number of ranks (" + std::to_string(comm->getSize()) +
                        ")");
  groups_ = std::make_unique<CommControlGroups>(comm, controlGroups);

  // Neural control (issue 5): per step, the controller picks the inputs of the controlled
  // groups that keep the control points at their goals (eq. 25), each candidate a full step
  // solve from the committed state; the winner's state is committed.
  control_ = std::make_unique<ControlSetup>(buildControl(deck, scene));
  buildSolvers(deck, physicalVolumetric);

  // Checked before the output directory is cleared: a bad deck leaves an earlier run intact.
  for (const auto &[key, sets] : {std::make_pair("resultant face sets", &output_.resultantFaceSets),
                                  std::make_pair("volume face sets", &output_.volumeFaceSets)})
    for (const auto &name : *sets)
      if (!scene.mesh.faceSets.count(name))
        throw io::DeckError(deck.where({"Output", key}) + ": no face set '" + name + "'");
  dir_ = options.outputDirectory.empty() ? std::filesystem::path(output_.directory) : options.outputDirectory;
  deckListing_ = parameterListing(D);
  std::unique_ptr<Restart> restart;
  if (!options.restartDirectory.empty()) {
    if (!options.outputDirectory.empty())
      throw io::DeckError("--restart continues in the directory it names; leave out --output");
    dir_ = options.restartDirectory;
    restart = readRestart(deck, dir_);
  }
  if (root_ && !restart) prepareOutputDirectory(dir_);
  comm->barrier();
  recorder_ = std::make_unique<StepRecorder>(*results_, dir_, output_.fields, root_, output_.resultantFaceSets,
                                             output_.volumeFaceSets, restart ? &restart->outputs : nullptr);
  checkpoints_ = std::make_unique<io::CheckpointStore>(dir_);
  checkpointEvery_ = output_.checkpointEvery; // none on an arc-length path
  every_ = output_.every;

  describeRun(deck, physicalVolumetric);

  committed_ =
      std::make_unique<StepState>(assembler_->layout().ownedMap(), assembler_->layout().numLocalElements());
  stepStart_ = std::make_unique<StepState>(*committed_);
  previous_ = std::make_unique<StepState>(*committed_);
  // auto: not with the penalty method, whose kappa (5000 mu at nu = 0.4999) multiplies the volume
  // error of an extrapolated displacement into its pressures (doc/theory.md, bench/README.md).
  extrapolate_ = time_.predictor == Predictor::linearExtrapolation ||
                 (time_.predictor == Predictor::automatic && incompressibility_.method != IncompressibilityMethod::penalty);
  const assembly::MuscleFields initialMuscle = assembly::updateMuscleHistory(*results_, committed_->u, *muscleHistory_);
  std::vector<double> initialInputs;
  for (std::size_t g = 0; g < scene.muscles.groups.size(); ++g)
    initialInputs.push_back(muscleHistory_->input(static_cast<int>(g), 0.0));
  if (!restart) {
    recorder_->record(0.0, committed_->u, committed_->lambda, true, initialMuscle, initialInputs);
    writeSummary();
  }
  stepsStart_ = Clock::now();
  installStopSignalHandlers();
  if (root_) onStopSignal([this](int signal) { writeInterruptedSummary(signal); });

  if (controlGroups > 1 &&
      !(control_->enabled && control_->parameters.type == control::ControllerType::geneticAlgorithm))
    throw io::DeckError("--control-groups " + std::to_string(controlGroups) +
                        " needs Control/type = genetic algorithm (the candidates it shares out)");
  committedStretch_ = initialMuscle.groupMeanStretch;
  if (control_->enabled) setUpController(restart ? &restart->outputs : nullptr);
  if (restart) restoreState(*restart);
}

// The assembly, the model evaluator with its linear solver, Newton, the Uzawa loop and the
// path's monitors, on the control group's communicator.
void Simulation::buildSolvers(const io::Deck &deck, const std::vector<materials::VolumetricEnergy> &physicalVolumetric) {
  const RunOptions &options = options_;
  model::Scene &scene = *scene_;
  const double mu = scene.tissues[0].matrix->shearModulus();
  const Teuchos::RCP<const Teuchos::Comm<int>> &solverComm = groups_->groupComm();
  assembly::DofLayout layout = assembly::distributeScene(scene, solverComm);
  muscleHistory_ = std::make_unique<model::MuscleHistory>(scene.muscles, layout.localElements);
  assembler_ = Teuchos::rcp(new assembly::Assembler(scene, std::move(layout), *muscleHistory_, solverComm));
  results_ = std::make_unique<const assembly::ResultEvaluator>(*assembler_);
  LinearSolverContext context{assembly::coordinates(*assembler_), assembly::rigidBodyModes(*assembler_),
                              solverComm->getSize(), assembler_->layout().numGlobalDofs(), scene.symmetricTangent};
  Teuchos::RCP<assembly::MixedPressureState> mixedPressure;
  if (incompressibility_.method == IncompressibilityMethod::mixed) {
    requireMixedCompatible(linear_, controlled_, scene);
    mixedPressure = Teuchos::rcp(new assembly::MixedPressureState(physicalVolumetric[0], mu));
  }
  // The control points are the model's response (their sensitivities to the neural inputs).
  model_ = Teuchos::rcp(new assembly::ModelEvaluator(
      assembler_, mixedPressure.is_null() ? buildLinearSolver(linear_, context)
                                          : buildMixedBlockSolver(linear_, context, mixedPressure),
      muscleHistory_.get(), control_->enabled ? control_->pointNodes : std::vector<mesh::NodeId>{}));
  model_->setMixedPressure(mixedPressure);
  for (const auto &x : scene.mesh.nodes) lengthScale_ = std::max(lengthScale_, x.norm());
  planes_ = model::findSymmetryPlanes(scene.mesh, scene.dirichlet);
  onPath_ = time_.pathFollowing == PathFollowing::arcLength;
  if (onPath_ || time_.atLimitPoint == AtLimitPoint::follow) {
    requireArcLengthCompatible(deck, incompressibility_, controlled_, scene, options,
                               onPath_ ? "path following" : "at a limit point");
    arcLength_ = std::make_unique<ArcLengthSettings>(arcLengthSettings(time_, newtonParameters_, linear_, *assembler_));
  }
  if (mixedPressure.is_null() && !onPath_ && time_.atLimitPoint != AtLimitPoint::ignore)
    limit_ = std::make_unique<LimitPointMonitor>(steps_->nominalStep(), time_.limitPointTolerance);
  keptScope_ = keptReuseScope(linear_, context, !mixedPressure.is_null());
  newton_ = std::make_unique<NewtonSolver>(model_, newtonParameters_, lengthScale_, linear_.tolerance,
                                           keptScope_ != ReuseScope::newtonSolve);
  uzawa_ = std::make_unique<UzawaLoop>(*results_, *newton_, incompressibility_, physicalVolumetric);
  // A raised kappa_AL reaches the tangent through the tissue's volumetric law (the Assembler's).
  uzawa_->onKappaRaised([this](std::size_t tissue, double kappaT) {
    model::Tissue &t = scene_->tissues[tissue];
    t.volumetric = t.volumetric.withKappa(kappaT);
    if (talk_)
      std::printf("  note: the Uzawa loop contracts slowly in tissue '%s': kappa_AL raised to %.3g mu for the rest of "
                  "the run\n", t.name.c_str(), uzawa_->penaltyRatios()[tissue]);
  });
  // What Linear solver/type = auto chose (the displacement block's preconditioner with mixed).
  doc_["linear_solver"] = usesDirectSolve(linear_, context) ? "direct (" + linear_.directSolverName + ")"
                                                                  : "iterative (" + linear_.preconditionerName + ")";
  if (linear_.type == LinearSolverType::automatic && usesDirectSolve(linear_, context))
    warnIgnoredIterativeSettings(deck, assembler_->layout().numGlobalDofs());
}

// Linear solver/type = auto solved directly (a small problem on one rank): settings the deck
// gives for the iterative solver would pass silently, so each is named, on stderr (also with
// --quiet) and in summary.json's warnings.
void Simulation::warnIgnoredIterativeSettings(const io::Deck &deck, long long unknowns) {
  static const char *const iterativeOnly[] = {
      "preconditioner", "MueLu smoother", "smoother degree", "vertex-patch levels", "patch sweeps",
      "Chebyshev eigenvalue method", "Chebyshev eigenvalue iterations", "Chebyshev eigenvalue ratio", "MueLu reuse",
      "MueLu reuse scope", "coarse size",
      "FROSch coarse space", "FROSch overlap", "Ifpack2 type"};
  for (const char *name : iterativeOnly) {
    if (!deck.given({"Linear solver", name})) continue;
    const std::string text = deck.where({"Linear solver", name}) + " is not used: Linear solver/type = auto solves " +
                             std::to_string(unknowns) + " unknowns on one rank directly (at most 'direct up to'); "
                             "set type = iterative to use it";
    doc_["warnings"].push_back(text);
    if (root_) std::fprintf(stderr, "glossa: warning: %s\n", text.c_str());
  }
}

// What summary.json says of the run before its first step, and the console's first lines.
void Simulation::describeRun(const io::Deck &deck, const std::vector<materials::VolumetricEnergy> &physicalVolumetric) {
  const model::Scene &scene = *scene_;
  // The summary's kappa/mu figures are the Material section's tissue's (tissues[0]).
  const double mu = scene.tissues[0].matrix->shearModulus();
  const Teuchos::RCP<const Teuchos::Comm<int>> &comm = comm_;
  const Teuchos::RCP<const Teuchos::Comm<int>> &solverComm = groups_->groupComm();
  const int controlGroups = options_.controlGroups;
  doc_["deck"] = deck.file();
  doc_["converged"] = false;
  doc_["running"] = true;
  doc_["ranks"] = comm->getSize();
  doc_["control_groups"] = controlGroups;
  {
    // The partition's balance (per rank of a control group).
    std::vector<double> mine(solverComm->getSize(), 0.0), all(mine.size(), 0.0);
    mine[solverComm->getRank()] = static_cast<double>(assembler_->layout().numLocalElements());
    Teuchos::reduceAll(*solverComm, Teuchos::REDUCE_SUM, static_cast<int>(mine.size()), mine.data(), all.data());
    doc_["elements_per_rank"] = all;
    doc_["partitioner"] = scene.partitioner == model::Partitioner::coordinateBisection ? "coordinate bisection"
                          : scene.partitioner == model::Partitioner::zoltan2Rcb        ? "Zoltan2 RCB"
                                                                                        : "Zoltan2 multijagged";
  }
  doc_["dofs"] = assembler_->layout().numGlobalDofs();
  doc_["elements"] = scene.mesh.numElements();
  doc_["incompressibility"] = methodName(incompressibility_.method);
  doc_["kappa_tangent"] = scene.tissues[0].volumetric.kappa();
  doc_["kappa_over_mu"] = scene.tissues[0].volumetric.kappa() / mu;
  doc_["kappa_physical_over_mu"] = physicalVolumetric[0].kappa() / mu; // inf is written as null
  doc_["tissues"] = nlohmann::json::array();
  for (std::size_t t = 0; t < scene.tissues.size(); ++t) {
    const auto &tissue = scene.tissues[t];
    const auto elements = scene.elementTissue.empty()
                              ? scene.mesh.numElements()
                              : static_cast<std::size_t>(std::count(scene.elementTissue.begin(), scene.elementTissue.end(), static_cast<int>(t)));
    doc_["tissues"].push_back({{"name", tissue.name}, {"elements", elements}, {"mu", tissue.matrix->shearModulus()},
                               {"kappa_physical", physicalVolumetric[t].kappa()}, {"kappa_tangent", tissue.volumetric.kappa()},
                               {"density", tissue.density}});
  }
  if (uzawa_->augmentedLagrangian()) doc_["kappa_AL_over_mu"] = UzawaLoop::augmentationKappa(incompressibility_, mu) / mu;
  doc_["steps"] = nlohmann::json::array();

  if (talk_)
    std::printf("glossa: %s  %zu elements  %lld dofs  %d rank(s)  %s (kappa/mu = %.3g)\n", deck.file().c_str(),
                scene.mesh.numElements(), static_cast<long long>(assembler_->layout().numGlobalDofs()),
                comm->getSize(), methodName(incompressibility_.method), scene.tissues[0].volumetric.kappa() / mu);
  if (talk_)
    for (const std::string &note : scene.meshNotes) std::printf("glossa: note: %s\n", note.c_str());
}

void Simulation::setUpController(const OutputMark *resume) {
  const model::Scene &scene = *scene_;
  uzawa_->allowKappaRaises(false); // every candidate of a step must see the same kappa_AL
  std::optional<std::uintmax_t> resumeAt;
  if (resume && resume->csvBytes.count("controls.csv")) resumeAt = resume->csvBytes.at("controls.csv");
  if (root_)
    controls_ = std::make_unique<io::KeyedCsvWriter>(
        dir_ / "controls.csv", "group", std::vector<std::string>{"u [-]", "evaluated [-]", "objective [m]", "candidates [-]"},
        resumeAt);
  ControlDriverSetup setup;
  setup.parameters = control_->parameters;
  for (const auto &g : scene.muscles.groups) setup.groupNames.push_back(g.name);
  setup.controlled = control_->groups;
  setup.referencePositions.resize(3, static_cast<Eigen::Index>(control_->pointNodes.size()));
  for (std::size_t p = 0; p < control_->pointNodes.size(); ++p)
    setup.referencePositions.col(static_cast<Eigen::Index>(p)) = scene.mesh.nodes[control_->pointNodes[p]];
  setup.goals = control_->goals;
  setup.weights = control_->weights;
  setup.talk = detail_;
  plant_ = std::make_unique<CandidatePlant>(*this);
  driver_ = std::make_unique<ControlDriver>(std::move(setup), *plant_, *groups_);
}

Simulation::~Simulation() {
  if (root_) onStopSignal({});
}

bool Simulation::finished() const { return !(t_ < steps_->endTime() * (1.0 - 1e-12)); }

void Simulation::writeSummary() {
  doc_["wall_seconds"] = since(start_);
  doc_["assembly_seconds"] = model_->assemblySeconds();
  // Element passes NOX asked for: residuals (each also assembles the tangent where it can), the
  // tangents among them, and the tangent requests the residual pass had already served.
  doc_["residual_evaluations"] = model_->residualEvaluations();
  doc_["tangent_evaluations"] = model_->tangentEvaluations();
  doc_["tangents_from_residual_pass"] = model_->tangentsFromResidualPass();
  doc_["residual_only_passes"] = model_->residualOnlyPasses();
  // NOX's own timers split the linear solves into preconditioner set-up and Krylov iterations.
  doc_["preconditioner_setup_seconds"] = timerSeconds("NOX Total Preconditioner Construction") - setupAtStart_;
  doc_["linear_solve_seconds"] = timerSeconds("NOX Total Linear Solve") - solveAtStart_;
  double peak = peakMemoryMegabytes(), peakMax = 0.0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, peak, Teuchos::outArg(peakMax));
  doc_["peak_memory_mb_per_rank"] = peakMax;
  if (!root_) return;
  std::lock_guard<std::recursive_mutex> lock(summaryMutex_);
  if (!summary_) summary_ = std::make_unique<io::SummaryWriter>(dir_ / "summary.json");
  summary_->root() = doc_;
  // The watcher wrote "interrupted" already; a step committed since keeps saying so.
  if (interruptedBy_ != 0 && !doc_.contains("interrupted")) markInterrupted(summary_->root(), interruptedBy_);
  summary_->write();
}

namespace {
std::vector<double> ownedValues(const assembly::Vector &v) {
  const auto data = v.getData();
  return std::vector<double>(data.begin(), data.end());
}

void assignOwnedValues(assembly::Vector &v, const nlohmann::json &values, const char *what) {
  const auto x = values.get<std::vector<double>>();
  auto data = v.getDataNonConst();
  if (x.size() != static_cast<std::size_t>(data.size()))
    throw io::OutputError(std::string("the checkpoint's ") + what + " has " + std::to_string(x.size()) + " values here, " +
                          std::to_string(data.size()) + " expected (another mesh or partition)");
  std::copy(x.begin(), x.end(), data.begin());
}

std::vector<double> elementValues(const nlohmann::json &values, std::size_t expected, const char *what) {
  auto x = values.get<std::vector<double>>();
  if (x.size() != expected)
    throw io::OutputError(std::string("the checkpoint's ") + what + " has " + std::to_string(x.size()) +
                          " element values here, " + std::to_string(expected) + " expected (another mesh or partition)");
  return x;
}

} // namespace

nlohmann::json Simulation::runState() {
  nlohmann::json run;
  run["deck"] = deckListing_;
  run["ranks"] = comm_->getSize();
  run["control_groups"] = options_.controlGroups;
  run["step"] = stepNumber_;
  run["time"] = t_;
  run["previous_dt"] = previousDt_;
  const StepSizeController::State steps = steps_->state();
  run["step_size"] = {steps.stepSize, steps.successes};
  if (limit_) run["limit_point"] = limit_->state();
  run["softening_said"] = softeningSaid_;
  run["penalty_ratios"] = uzawa_->penaltyRatios();
  run["committed_stretch"] = committedStretch_;
  if (driver_) {
    const auto memory = driver_->memory();
    run["control_memory"] = {memory.first, memory.second};
  }
  OutputMark outputs = recorder_->mark();
  if (controls_) outputs.csvBytes["controls.csv"] = controls_->bytes();
  run["outputs"] = toJson(outputs);
  run["summary"] = doc_;
  return run;
}

void Simulation::writeCheckpoint() {
  if (checkpointedStep_ == stepNumber_) return;
  nlohmann::json part;
  part["u"] = ownedValues(committed_->u);
  part["lambda"] = committed_->lambda;
  if (extrapolate_) {
    part["previous_u"] = ownedValues(previous_->u);
    part["previous_lambda"] = previous_->lambda;
  }
  part["muscle"] = toJson(muscleHistory_->snapshot());
  part["multiplier_prediction"] = multiplierPredictor_.toJson();
  if (root_) part["run"] = runState();
  // Published only once every rank's part is on disk; a rank that cannot write stops them all.
  std::string error;
  try {
    checkpoints_->writePart(stepNumber_, comm_->getRank(), part);
  } catch (const std::exception &e) {
    error = e.what();
  }
  int failed = error.empty() ? 0 : 1, anyFailed = 0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, failed, Teuchos::outArg(anyFailed));
  if (anyFailed) throw io::OutputError(error.empty() ? "another rank could not write its checkpoint part" : error);
  if (root_) checkpoints_->publish(stepNumber_);
  comm_->barrier();
  checkpointedStep_ = stepNumber_;
}

std::unique_ptr<Simulation::Restart> Simulation::readRestart(const io::Deck &deck, const std::filesystem::path &dir) const {
  const io::CheckpointStore store(dir);
  const std::optional<int> step = store.latestStep();
  if (!step)
    throw io::DeckError("--restart " + dir.string() + ": no checkpoint there (" + (store.directory() / "latest").string() +
                        " is missing); a run writes one every Output/checkpoint every steps and when a signal stops it");
  auto restart = std::make_unique<Restart>();
  restart->step = *step;
  restart->part = store.readPart(*step, comm_->getRank());
  restart->run = (comm_->getRank() == 0 ? restart->part : store.readPart(*step, 0)).at("run");
  const nlohmann::json &run = restart->run;
  const std::string difference = firstDifference(run.at("deck").get<std::string>(), parameterListing(deck.root()));
  if (!difference.empty())
    throw io::DeckError("--restart " + dir.string() + ": the deck is not the one the run was started with (" + difference +
                        "); a restart continues the same run, with the same deck and --set values");
  if (run.at("ranks").get<int>() != comm_->getSize() || run.at("control_groups").get<int>() != options_.controlGroups)
    throw io::DeckError("--restart " + dir.string() + ": the run was made on " + std::to_string(run.at("ranks").get<int>()) +
                        " rank(s) in " + std::to_string(run.at("control_groups").get<int>()) +
                        " control group(s); restart it on as many (its checkpoint is split by rank)");
  restart->outputs = outputMarkFromJson(run.at("outputs"));
  return restart;
}

void Simulation::restoreState(const Restart &restart) {
  const nlohmann::json &part = restart.part, &run = restart.run;
  assignOwnedValues(committed_->u, part.at("u"), "displacement");
  committed_->lambda = elementValues(part.at("lambda"), committed_->lambda.size(), "multipliers");
  if (extrapolate_) {
    assignOwnedValues(previous_->u, part.at("previous_u"), "previous displacement");
    previous_->lambda = elementValues(part.at("previous_lambda"), previous_->lambda.size(), "previous multipliers");
  }
  muscleHistory_->restore(muscleSnapshotFromJson(part.at("muscle")));
  // A checkpoint written before the prediction existed has none: that run's next step starts
  // from its committed multipliers.
  if (part.contains("multiplier_prediction"))
    multiplierPredictor_.restore(part.at("multiplier_prediction"), committed_->lambda.size());
  stepNumber_ = run.at("step").get<int>();
  t_ = run.at("time").get<double>();
  previousDt_ = run.at("previous_dt").get<double>();
  steps_->restore({run.at("step_size").at(0).get<double>(), run.at("step_size").at(1).get<int>()});
  if (limit_ && run.contains("limit_point")) limit_->restore(run.at("limit_point"));
  softeningSaid_ = run.at("softening_said").get<bool>();
  uzawa_->restorePenaltyRatios(run.at("penalty_ratios").get<std::vector<double>>());
  committedStretch_ = run.at("committed_stretch").get<std::vector<double>>();
  if (driver_ && run.contains("control_memory"))
    driver_->restoreMemory({run.at("control_memory").at(0).get<control::Genome>(),
                            run.at("control_memory").at(1).get<control::Genome>()});
  doc_ = run.at("summary");
  if (!doc_.contains("restarts")) doc_["restarts"] = nlohmann::json::array();
  doc_["restarts"].push_back({{"after_step", stepNumber_}, {"time", t_}});
  checkpointedStep_ = stepNumber_;
  stepsStartTime_ = t_;
  if (talk_)
    std::printf("glossa: restarting after step %d (t = %.6g s) from %s\n", stepNumber_, t_,
                (checkpoints_->directory()).c_str());
  writeSummary();
}

void Simulation::writeInterruptedSummary(int signal) {
  std::lock_guard<std::recursive_mutex> lock(summaryMutex_);
  interruptedBy_ = signal;
  if (!summary_) return;
  markInterrupted(summary_->root(), signal);
  try {
    summary_->write();
  } catch (const std::exception &) {
    // Nothing more can be done on this thread; the main thread reports output errors.
  }
}

Simulation::Attempt Simulation::solveStep(double time, double dt, StepState &state, bool quiet) {
  Attempt out;
  if (keptScope_ == ReuseScope::step) newton_->forgetLinearSolver();
  assembler_->applyDirichlet(state.u, time);
  model_->setTime(time);
  model_->setMultipliers(state.lambda);
  muscleHistory_->beginStep(time, dt); // trial activation; lambda_c stays at its committed value

  // The Newton tolerance scales with the load: the external force and the step's initial
  // residual, which the first Newton solve assembles anyway.
  const double externalForce = assembler_->externalForceNorm(time);
  const double relative = newton_->relativeResidualTolerance();
  const NewtonSolver::ToleranceRule tolerance = [externalForce, relative](double initialResidualNorm) {
    double reference = std::max(externalForce, initialResidualNorm);
    if (!(reference > 0.0)) reference = 1.0;
    return relative * reference;
  };

  const bool progress = detail_ && !quiet;
  auto onNewton = [&](int k, double normF, int krylov) {
    if (progress) std::printf("    newton %2d  |f| = %.3e  krylov %d\n", k, normF, krylov);
  };
  auto onUzawa = [&](int k, const NewtonResult &n, const DilatationError &e) {
    if (progress)
      std::printf("  uzawa %d: newton %d  krylov %d  dilatation error max %.2e  mean %.2e  max|theta-1| %.2e\n", k,
                  n.iterations, n.linearIterations, e.max, e.mean, e.maxVolumeChange);
  };
  out.uzawa = uzawa_->solve(state.u, state.lambda, tolerance, onNewton, onUzawa);
  // The history at the converged state: lambda_c of every point with this step's activation.
  if (out.uzawa.converged) out.muscle = assembly::updateMuscleHistory(*results_, state.u, *muscleHistory_);
  // What the Gauss points cannot see: the smallest det F at the elements' corners, at all corners
  // and at regular ones. Reported per step (summary.json, and a note when a corner has turned
  // over), not refused: in the tongue scenes, whose Gauss points and answers are sound, corners
  // turn over to det F = -8.5 (s8_4_sg) and even regular corners, whose reference det is at least
  // 0.2 of their element's mean, to -1.1 (s8_5 passive supine) and -0.21 (s8_4_sg), so no corner
  // threshold tells those from an element inside out as a whole (doc/theory.md).
  if (out.uzawa.converged) {
    const auto worst = results_->worstCorner(state.u);
    out.minCornerJ = worst.J;
    out.cornerElement = worst.element;
    out.minRegularCornerJ = worst.regularJ;
    out.regularCornerElement = worst.regularElement;
  }
  out.ok = out.uzawa.converged && out.muscle.valid;
  if (out.ok) refuseInsideOut(state, out);
  if (!out.ok && out.why.empty()) {
    const UzawaResult &r = out.uzawa;
    const NewtonResult &last = r.newton.back();
    out.why = !out.muscle.valid ? "a contractile-stretch solve failed at the converged state"
              : r.elementInverted ? "an element inverted (J <= 0) or a muscle point law failed"
              : !last.failure.empty() ? last.failure.substr(0, last.failure.find('\n'))
              : !last.converged ? "Newton did not converge"
                                : "Uzawa did not reach the dilatation tolerance";
  }
  return out;
}

void Simulation::refuseInsideOut(const StepState &state, Attempt &attempt) const {
  if (planes_.empty()) return;
  const model::PlaneCrossing deepest = model::deepestCrossing(planes_, scene_->mesh, results_->gatherDisplacement(state.u));
  // Material across a symmetry plane overlaps its mirror image. A node next to a plane but not
  // on it (on another plane's edge) may sit a little across in a sound state (2.6e-9 m, 1.3e-6 of
  // the thick sphere's size, at p = 0.72 mu): 1e-3 of the body's size is the threshold.
  if (!(deepest.distance < -1e-3 * lengthScale_)) return;
  const model::SymmetryPlane &plane = planes_[deepest.plane];
  const std::string &name = scene_->dirichlet[plane.condition].name;
  const char axis = "xyz"[plane.axis];
  char why[400];
  std::snprintf(why, sizeof why,
                "the converged state is inside out: the body has passed through its symmetry plane '%s' (%c = %.6g m), "
                "node %zu lying %.3g m on the far side, where its mirror image is",
                name.c_str(), axis, plane.position, static_cast<std::size_t>(deepest.node), -deepest.distance);
  attempt.ok = false; // on a softened path the monitor counts it as a failure past the maximum
  attempt.why = why;
  attempt.insideOut = {{"condition", name}, {"node", deepest.node}, {"distance", -deepest.distance}};
}

void Simulation::applyControlInputs(const std::vector<double> &inputs) {
  for (int g : control_->groups) muscleHistory_->overrideInput(g, inputs[g]);
}

Eigen::Matrix3Xd Simulation::controlPointDisplacement(const StepState &state) const {
  const std::vector<double> all = results_->gatherDisplacement(state.u);
  Eigen::Matrix3Xd d(3, static_cast<Eigen::Index>(control_->pointNodes.size()));
  for (std::size_t p = 0; p < control_->pointNodes.size(); ++p) {
    const auto n = control_->pointNodes[p];
    d.col(static_cast<Eigen::Index>(p)) = Eigen::Vector3d(all[3 * n], all[3 * n + 1], all[3 * n + 2]);
  }
  return d;
}

bool Simulation::attemptStep() {
  const double dt = steps_->nextStep(t_);
  const bool extrapolated = extrapolate_ && previousDt_ > 0.0;
  if (attemptStepFrom(dt, extrapolated) || !extrapolated || trial_->attempt.unstable) return trial_->attempt.ok;
  // The extrapolation can overshoot where the motion stops short, e.g. a muscle's jump from rest
  // in a first step carried on into the next (the protrusion scene: elements inverted, 8 steps
  // became 16 with cut-backs alone; bench/README.md).
  if (talk_)
    std::printf("  step failed at t = %.6g from the extrapolated state: %s; again from the last converged state\n",
                trial_->time, trial_->attempt.why.c_str());
  doc_["predictor_retries"] = doc_.value("predictor_retries", 0) + 1;
  return attemptStepFrom(dt, false);
}

bool Simulation::attemptStepFrom(double dt, bool extrapolated) {
  // The start of this step's solves: the committed state, or its linear extrapolation from the
  // step before (the multipliers too, so the Uzawa loop starts nearer its fixed point); with the
  // augmented Lagrangian the multipliers then come from MultiplierPredictor, one update ahead.
  stepStart_->assign(*committed_);
  if (extrapolated) {
    const double ratio = dt / previousDt_;
    stepStart_->u.update(-ratio, previous_->u, 1.0 + ratio);
    for (std::size_t e = 0; e < stepStart_->lambda.size(); ++e)
      stepStart_->lambda[e] += ratio * (committed_->lambda[e] - previous_->lambda[e]);
  }
  multiplierPredictor_.predict(dt, stepStart_->lambda);
  trial_ = std::make_unique<Trial>(t_ + dt, dt, model_->assemblySeconds(), *stepStart_);
  if (detail_) std::printf("step %d  t = %.6g  dt = %.3g\n", stepNumber_ + 1, trial_->time, dt);
  if (driver_) controlledStep(*trial_);
  else trial_->attempt = solveStep(trial_->time, dt, trial_->state, false);
  if (trial_->attempt.ok && limit_) checkPathStiffness(*trial_);
  return trial_->attempt.ok;
}

void Simulation::checkPathStiffness(Trial &trial) {
  model_->setTime(trial.time);
  model_->setMultipliers(trial.state.lambda);
  const PathStiffness measured =
      pathStiffness(*assembler_, *newton_, trial.state.u, trial.time, trial.dt, trial.state.lambda);
  if (!measured.note.empty() && talk_)
    std::printf("  note: the stiffness along the path at t = %.6g was not measured: %s\n", trial.time, measured.note.c_str());
  Attempt &a = trial.attempt;
  a.pathStiffness = limit_->relativeStiffness(measured.stiffness);
  if (!LimitPointMonitor::beyond(a.pathStiffness)) return;
  a.ok = false;
  a.unstable = true;
  char why[200];
  std::snprintf(why, sizeof why,
                "the converged state is past a limit point (the tangent's stiffness along the path is %.3g of the "
                "first step's: an unstable equilibrium)", a.pathStiffness);
  a.why = why;
}


void Simulation::controlledStep(Trial &trial) {
  trial.control = driver_->step(stepNumber_, committedStretch_);
  if (!trial.control.found()) {
    trial.attempt.why = "no candidate input converged";
    return;
  }
  plant_->adoptKept(trial);
}

bool Simulation::rollBack() {
  const std::string &why = trial_->attempt.why;
  if (talk_) std::printf("  step failed at t = %.6g: %s; cutting back\n", trial_->time, why.c_str());
  if (!trial_->attempt.insideOut.is_null()) {
    nlohmann::json refusal = trial_->attempt.insideOut;
    refusal["time"] = trial_->time;
    doc_["inside_out_refusals"].push_back(refusal);
  }
  if (limit_) {
    // Where it moves most: along the unstable step, or (Newton found nothing) in all so far.
    assembly::Vector motion(trial_->state.u, Teuchos::Copy);
    if (trial_->attempt.unstable) motion.update(-1.0, committed_->u, 1.0);
    else motion.assign(committed_->u);
    limit_->refused(t_, trial_->time, trial_->attempt.unstable, largestMotion(*results_, motion).node);
  }
  const bool stepLeft = steps_->cutBack();
  if (limit_ && (limit_->located(steps_->stepSize()) || (!stepLeft && limit_->located(0.0)))) {
    const Eigen::Vector3d x = scene_->mesh.nodes[limit_->node()];
    doc_["limit_point"] = limit_->record(x);
    if (arcLength_) { // at a limit point = follow: the path goes on from the last accepted state
      switchToPath_ = true;
      if (talk_)
        std::printf("  note: a limit point of the load path between t = %.6g and %.6g s (summary.json: limit_point); "
                    "following the path past it by arc-length continuation\n",
                    doc_["limit_point"]["bracket"][0].get<double>(), doc_["limit_point"]["bracket"][1].get<double>());
      return false;
    }
    failure_ = limit_->description(x);
    converged_ = false;
    return false;
  }
  if (stepLeft) return true;
  failure_ = "step to t = " + std::to_string(trial_->time) + " failed (" + why + ") below the minimum step size";
  converged_ = false;
  return false;
}

void Simulation::commitTrial() {
  const Trial &trial = *trial_;
  if (extrapolate_) {
    previous_->assign(*committed_);
    previousDt_ = trial.dt;
  }
  committed_->assign(trial.state);
  // A controlled step's winner may have been solved by another control group, whose statistics
  // carry no multipliers: every group takes them from the committed state alike.
  if (driver_ && uzawa_->augmentedLagrangian() && !uzawa_->mixedPressure())
    multiplierPredictor_.commit(
        uzawa_->nextMultipliers(results_->elementDilatations(committed_->u, committed_->lambda)), trial.dt);
  else
    multiplierPredictor_.commit(trial.attempt.uzawa.nextMultipliers, trial.dt);
  t_ = trial.time;
  ++stepNumber_;
  steps_->accept();
  if (limit_ && !onPath_) {
    limit_->accepted(t_, trial.attempt.pathStiffness);
    if (trial.attempt.pathStiffness < LimitPointMonitor::kSoftened && !softeningSaid_ && talk_)
      std::printf("  note: the load path has softened: the tangent's stiffness along the path is %.3g of the first "
                  "step's (a limit point may be near)\n", trial.attempt.pathStiffness);
    softeningSaid_ = softeningSaid_ || trial.attempt.pathStiffness < LimitPointMonitor::kSoftened;
  }
  // The muscle history is committed after the output, whose stresses are those of the converged
  // state: this step's activation with the committed lambda_c it was solved with.
  std::unique_lock<std::recursive_mutex> output(summaryMutex_);
  record(trial);
  committedStretch_ = trial.attempt.muscle.groupMeanStretch;
  muscleHistory_->commit();
  const UzawaResult &r = trial.attempt.uzawa;
  if (talk_ && onPath_) {
    std::printf("step %d  t = %.6g (load %.4g of the end time's)  newton %d  dilatation error %.1e  [%s elapsed]\n",
                stepNumber_, t_, t_ / steps_->endTime(), r.newtonIterations, r.dilatation.max,
                readableDuration(since(stepsStart_)).c_str());
  } else if (talk_) {
    // step k/N with N from the step size now (the controller may still cut back or grow it), and
    // the time left from the wall time per simulated second so far.
    const double end = steps_->endTime(), elapsed = since(stepsStart_);
    const long left = t_ < end ? std::lround(std::ceil((end - t_) / trial.dt - 1e-9)) : 0;
    const double remaining = t_ > stepsStartTime_ ? elapsed * (end - t_) / (t_ - stepsStartTime_) : 0.0;
    std::printf("step %d/%ld  t = %.6g of %.6g s  newton %d  krylov %d  uzawa %d  dilatation error %.1e%s  "
                "[%s elapsed, about %s left]\n",
                stepNumber_, stepNumber_ + left, t_, end, r.newtonIterations, r.linearIterations, r.solves,
                r.dilatation.max, controlLine_.c_str(), readableDuration(elapsed).c_str(), readableDuration(remaining).c_str());
  }
  writeSummary();
  output.unlock();
  if (checkpointEvery_ > 0 && stepNumber_ % checkpointEvery_ == 0 && !onPath_) writeCheckpoint();
}

void Simulation::record(const Trial &trial) {
  const model::MuscleHistory &history = *muscleHistory_;
  const UzawaResult &r = trial.attempt.uzawa;
  const assembly::MuscleFields &muscle = trial.attempt.muscle;
  const auto reactions = recorder_->record(t_, committed_->u, committed_->lambda,
                                           finished() || stepNumber_ % every_ == 0, muscle, history.trialInput(),
                                           fieldsStamp());
  nlohmann::json step;
  step["time"] = t_;
  step["dt"] = trial.dt;
  step["newton_iterations"] = r.newtonIterations;
  if (!onPath_) step["linear_iterations"] = r.linearIterations; // LOCA's bordered solves are not counted
  step["uzawa_iterations"] = r.solves;
  step["max_dilatation_error"] = r.dilatation.max;
  step["mean_dilatation_error"] = r.dilatation.mean;
  step["max_volume_change"] = r.dilatation.maxVolumeChange;
  step["min_corner_J"] = trial.attempt.minCornerJ;
  step["min_regular_corner_J"] = trial.attempt.minRegularCornerJ;
  if (r.augmentationRaises > 0) step["penalty_ratios"] = uzawa_->penaltyRatios();
  if (std::isfinite(trial.attempt.pathStiffness)) step["path_stiffness"] = trial.attempt.pathStiffness;
  if (!(trial.attempt.minCornerJ > 0.0) && talk_)
    std::printf("  note: element %lld has a corner turned over at t = %.6g (det F = %.3g there; its Gauss points are "
                "not inverted)\n", static_cast<long long>(trial.attempt.cornerElement), t_, trial.attempt.minCornerJ);
  step["seconds"] = since(trial.start);
  step["assembly_seconds"] = model_->assemblySeconds() - trial.assemblyAtStart;
  nlohmann::json histories = nlohmann::json::array();
  for (const auto &n : r.newton) histories.push_back({{"residual_norms", n.residualNorms}, {"krylov", n.linearIterationsPerStep}});
  step["newton_solves"] = histories;
  nlohmann::json reactionJson = nlohmann::json::object();
  for (const auto &[name, row] : reactions) reactionJson[name] = std::vector<double>(row.begin(), row.begin() + 3); // the force
  step["reactions"] = reactionJson;
  if (!scene_->muscles.groups.empty()) {
    nlohmann::json activation = nlohmann::json::object();
    for (const auto &[group, values] : recorder_->activationRows(muscle, history.trialInput()))
      activation[group] = {{"u", values[0]}, {"alpha", values[1]}, {"ffmr", values[2]}, {"mean_fibre_stretch", values[3]},
                           {"mean_contractile_stretch", values[4]}};
    step["activation"] = activation;
  }
  if (driver_) step["control"] = controlJson(trial);
  doc_["steps"].push_back(step);
}

nlohmann::json Simulation::controlJson(const Trial &trial) {
  const ControlStepResult &outcome = trial.control;
  const bool ga = control_->parameters.type == control::ControllerType::geneticAlgorithm;
  nlohmann::json c;
  c["objective"] = outcome.objective;
  c["candidates"] = outcome.candidates;
  if (ga) {
    c["generations"] = outcome.generations;
    // The Gauss-Newton step of the prediction seed (Control/prediction seed).
    if (outcome.sensitivities > 0) c["sensitivity_evaluations"] = outcome.sensitivities;
  } else {
    c["iterations"] = outcome.iterations;
    c["sensitivity_evaluations"] = outcome.sensitivities;
    c["sensitivity_krylov"] = outcome.sensitivityKrylov;
    if (outcome.sensitivityCheck >= 0.0) c["sensitivity_check"] = outcome.sensitivityCheck;
  }
  c["stop"] = outcome.stop;
  // Candidates whose solve failed are ranked last and otherwise silent: count them, with a reason.
  c["failed_candidates"] = outcome.failedCandidates;
  if (!outcome.firstFailure.empty()) c["first_candidate_failure"] = outcome.firstFailure;
  nlohmann::json inputs = nlohmann::json::object(), errors = nlohmann::json::object();
  std::vector<std::pair<std::string, std::vector<double>>> rows;
  for (int g : control_->groups) {
    const bool evaluated = std::find(outcome.evaluated.begin(), outcome.evaluated.end(), g) != outcome.evaluated.end();
    inputs[scene_->muscles.groups[g].name] = outcome.inputs[g];
    rows.push_back({scene_->muscles.groups[g].name,
                    {outcome.inputs[g], evaluated ? 1.0 : 0.0, outcome.objective, static_cast<double>(outcome.candidates)}});
  }
  for (std::size_t p = 0; p < control_->pointNames.size(); ++p)
    errors[control_->pointNames[p]] = outcome.pointErrors(static_cast<Eigen::Index>(p));
  c["inputs"] = inputs;
  c["point_errors"] = errors;
  if (controls_) controls_->append(t_, rows);
  char line[200];
  std::snprintf(line, sizeof line, "  control: eq. 25 %.3g m, %zu candidates (%zu failed), %s %d (%s)",
                outcome.objective, outcome.candidates, outcome.failedCandidates, ga ? "generations" : "iterations",
                ga ? outcome.generations : outcome.iterations, outcome.stop.c_str());
  controlLine_ = line;
  return c;
}

void Simulation::finish() {
  // Stopped by a signal: the committed state is sound, so it is kept for --restart.
  if (stoppedBy_ != 0 && checkpointEvery_ > 0 && !onPath_) writeCheckpoint();
  const std::vector<double> uAll = results_->gatherDisplacement(committed_->u);
  if (options_.finalDisplacement) *options_.finalDisplacement = uAll;
  nlohmann::json finals = nlohmann::json::object();
  for (const auto &[name, d] : recorder_->pointDisplacements(uAll)) finals[name] = {d.x(), d.y(), d.z()};
  doc_["final_displacement"] = finals;
  doc_["final_time"] = t_;
  doc_["converged"] = converged_;
  doc_["running"] = false;
  if (stoppedBy_ != 0) doc_["interrupted"] = signalName(stoppedBy_);
  if (!failure_.empty()) doc_["failure"] = failure_;
  writeSummary();
  if (converged_ && talk_) std::printf("glossa: done in %.2f s; results in %s\n", since(start_), dir_.c_str());
  // Why a run stopped goes to stderr, also with --quiet: a script must see it.
  if (!converged_ && root_) std::fprintf(stderr, "glossa: stopped: %s; results so far in %s\n", failure_.c_str(), dir_.c_str());
}

std::optional<double> Simulation::fieldsStamp() const {
  if (!onPath_) return std::nullopt;
  return pathStart_.time + (stepNumber_ - pathStart_.step) * steps_->nominalStep();
}

bool Simulation::stopRequested() {
  // Every rank agrees to stop at the same step boundary (a signal may reach them apart).
  int signal = stopSignal(), anySignal = 0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, signal, Teuchos::outArg(anySignal));
  if (anySignal == 0) return false;
  stoppedBy_ = anySignal;
  converged_ = false;
  failure_ = interruption(anySignal, static_cast<std::size_t>(stepNumber_), t_);
  return true;
}

void Simulation::followArcLength() {
  ArcLengthSettings settings = *arcLength_;
  settings.startTime = t_;
  onPath_ = true;
  pathStart_ = {t_, stepNumber_};
  model_->setMultipliers(committed_->lambda);
  model_->setTime(t_);

  double highest = t_; // the largest load so far, and whether the path has turned down from it
  bool turned = false;
  auto onPoint = [&](const ArcLengthPoint &point, const assembly::Vector &u) {
    trial_ = std::make_unique<Trial>(point.time, point.time - t_, model_->assemblySeconds(), *committed_);
    Attempt &a = trial_->attempt;
    trial_->state.u.assign(u);
    a.uzawa.converged = true;
    a.uzawa.solves = 1;
    a.uzawa.newtonIterations = point.newtonIterations;
    a.uzawa.dilatation = uzawa_->dilatationError(results_->elementDilatations(u, committed_->lambda));
    const auto worst = results_->worstCorner(u);
    a.minCornerJ = worst.J, a.cornerElement = worst.element;
    a.minRegularCornerJ = worst.regularJ, a.regularCornerElement = worst.regularElement;
    a.ok = true;
    refuseInsideOut(trial_->state, a);
    if (!a.ok) {
      doc_["inside_out_refusals"].push_back(a.insideOut);
      failure_ = "arc-length step " + std::to_string(point.step) + ": " + a.why;
      converged_ = false;
      return false;
    }
    commitTrial();
    if (point.time > highest) highest = point.time;
    else if (!turned) {
      // The load passed a maximum between the last two points: named once, as load control would.
      turned = true;
      doc_["load_maximum"] = {{"time", highest}, {"step", stepNumber_ - 1}};
      if (talk_) std::printf("  note: the path passed a load maximum near t = %.6g and follows the falling branch\n", highest);
    }
    const double largest = largestMotion(*results_, u).norm;
    if (stopRequested()) return false;
    return !(settings.stopAtDisplacement > 0.0 && largest >= settings.stopAtDisplacement);
  };
  const ArcLengthOutcome outcome = followPath(model_, committed_->u, settings, onPoint);
  doc_["path_following"] = {{"method", "arc length (LOCA)"}, {"steps", outcome.steps}, {"largest_time", highest}};
  if (!outcome.completed && failure_.empty()) {
    failure_ = outcome.failure;
    converged_ = false;
  }
}

nlohmann::json Simulation::run() {
  if (onPath_) {
    followArcLength();
    finish();
    return doc_;
  }
  while (!finished()) {
    if (stopRequested()) break;
    if (attemptStep()) commitTrial();
    else if (!rollBack()) break;
  }
  if (switchToPath_) followArcLength();
  finish();
  return doc_;
}

nlohmann::json runSimulation(const io::Deck &deck, const Teuchos::RCP<const Teuchos::Comm<int>> &comm,
                             const RunOptions &options) {
  Simulation simulation(deck, comm, options);
  return simulation.run();
}

} // namespace glossa::solvers
