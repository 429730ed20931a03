#include "solvers/run/RunSetup.hpp"

#include <algorithm>
#include <cstdio>

#include <Teuchos_CommHelpers.hpp>

#include "assembly/Assembler.hpp"
#include "assembly/ModelEvaluator.hpp"
#include "assembly/NullSpace.hpp"
#include "assembly/ResultEvaluator.hpp"
#include "input/AirflowParameters.hpp"
#include "input/AirwayParameters.hpp"
#include "input/SceneFactory.hpp"
#include "io/deck/DeckError.hpp"
#include "io/output/DirectoryLock.hpp"
#include "model/Scene.hpp"
#include "solvers/control/CommControlGroups.hpp"
#include "solvers/run/AirflowCoupling.hpp"
#include "solvers/incompressibility/UzawaLoop.hpp"
#include "solvers/linear/LinearSolverChoice.hpp"
#include "solvers/linear/MixedBlockSolver.hpp"
#include "solvers/nonlinear/NewtonSolver.hpp"
#include "solvers/parameters/RunChecks.hpp"

namespace glossa::solvers {

RunParts::~RunParts() = default;

StepSolverParts RunParts::stepSolverParts() const {
  return {*assembler, *model, *newton, *uzawa, *history, airflow.get()};
}

namespace {
// The scene (a command's adjustment applied), then each tissue's augmentation from its physical
// law: the scene keeps the physical laws, the tangent gets its kappa_t from the augmentation.
void buildScene(const io::Deck &deck, RunParts &run) {
  auto scene = std::make_unique<model::Scene>(input::buildScene(deck, run.config.time.rampEndTime));
  if (run.options.adjustScene) run.options.adjustScene(*scene);
  std::vector<materials::VolumetricEnergy> physical;
  std::vector<double> mu;
  for (const auto &tissue : scene->tissues) {
    physical.push_back(tissue.volumetric);
    mu.push_back(tissue.matrix->shearModulus());
  }
  run.scene = std::move(scene);
  run.augmentation = std::make_unique<Augmentation>(run.config.incompressibility, std::move(physical), std::move(mu));
}

ArcLengthSettings arcLengthSettings(const RunConfiguration &config, const assembly::Assembler &assembler) {
  ArcLengthSettings s;
  s.endTime = config.time.steps.endTime;
  s.stepSize = std::min(config.time.steps.nominal, s.endTime);
  s.minimumStepSize = config.time.steps.minimum;
  s.maximumSteps = config.time.arcLengthSteps;
  s.stopAtDisplacement = config.time.stopAtDisplacement;
  s.maximumNewtonIterations = config.newton.maximumIterations;
  // Relative to the load at the end time: the path's loads are fractions of it.
  const double reference = assembler.externalForceNorm(s.endTime);
  s.residualTolerance = config.newton.residualTolerance * (reference > 0.0 ? reference : 1.0);
  s.linearTolerance = config.linear.tolerance;
  return s;
}

// The assembly, the model evaluator with its linear solver, Newton and the Uzawa loop, on the
// control group's communicator; the control points are the model's response (their
// sensitivities to the neural inputs).
void buildSolvers(RunParts &run) {
  const RunConfiguration &config = run.config;
  const model::Scene &scene = *run.scene;
  const Teuchos::RCP<const Teuchos::Comm<int>> &solverComm = run.groups->groupComm();
  assembly::DofLayout layout = assembly::distributeScene(scene, solverComm);
  run.history = std::make_unique<model::MuscleHistory>(scene.muscles, layout.localElements);
  run.assembler = Teuchos::rcp(new assembly::Assembler(scene, std::move(layout), *run.history, solverComm,
                                                        &run.augmentation->tangentLaws()));
  // `direct` is left empty here: the plan below decides it, and the context then carries it.
  LinearSolverContext context{assembly::coordinates(*run.assembler),
                              assembly::rigidBodyModes(*run.assembler),
                              solverComm->getSize(),
                              run.assembler->layout().numGlobalDofs(),
                              scene.symmetricTangent,
                              std::nullopt};
  Teuchos::RCP<assembly::MixedPressureState> mixedPressure;
  if (config.incompressibility.method == IncompressibilityMethod::mixed)
    mixedPressure = Teuchos::rcp(
        new assembly::MixedPressureState(run.augmentation->physicalLaw(0), run.augmentation->mu(0)));
  // Resolved once: the factory, Newton (the kept scope) and the summary follow the plan.
  run.linearPlan = planLinearSolver(config.linear, context, !mixedPressure.is_null());
  context.direct = run.linearPlan.direct;
  run.model = Teuchos::rcp(new assembly::ModelEvaluator(
      run.assembler, mixedPressure.is_null() ? buildLinearSolver(config.linear, context)
                                             : buildMixedBlockSolver(config.linear, context, mixedPressure),
      run.history.get(), run.control.enabled ? run.control.pointNodes : std::vector<mesh::NodeId>{}));
  run.model->setMixedPressure(mixedPressure);
  double lengthScale = 0.0; // the largest |X| of the mesh
  for (const auto &x : scene.mesh.nodes) lengthScale = std::max(lengthScale, x.norm());
  run.newton = std::make_unique<NewtonSolver>(run.model, config.newton, lengthScale, config.linear.tolerance,
                                              run.linearPlan.keptScope != ReuseScope::newtonSolve, run.linearPlan.direct);
  // A controller's sensitivities: factored afresh by MUMPS of their own, or by Newton's solver.
  run.linearPlan.directSensitivities = run.linearPlan.direct;
  if (run.control.enabled && mixedPressure.is_null() &&
      directSensitivitySolve(config.linear, {context.globalRows, context.ranks})) {
    run.newton->setSensitivitySolver(directTangentSolver(config.linear, context));
    run.linearPlan.directSensitivities = true;
  }
  run.uzawa = std::make_unique<UzawaLoop>(assembly::ResultEvaluator(*run.assembler), *run.newton,
                                          config.incompressibility, *run.augmentation);
  // Every candidate of a controlled step must see the same kappa_AL.
  if (run.control.enabled) run.uzawa->allowKappaRaises(false);
  const bool onPath = config.time.pathFollowing == PathFollowing::arcLength;
  if (onPath || config.time.atLimitPoint == AtLimitPoint::follow)
    run.arcLength = std::make_unique<ArcLengthSettings>(arcLengthSettings(config, *run.assembler));
  run.solver = std::make_unique<StepSolver>(run.stepSolverParts(), scene, run.linearPlan.keptScope, run.detail, run.talk);
  // A dynamic step's tangent carries the mass: its stiffness along the path says nothing of a
  // limit point of the static load path.
  if (mixedPressure.is_null() && !onPath && config.time.atLimitPoint != AtLimitPoint::ignore &&
      !config.time.dynamics.dynamic())
    run.watch = std::make_unique<PathWatch>(
        *run.assembler, *run.model, *run.newton, config.time.steps.nominal, config.time.limitPointTolerance, run.talk,
        config.incompressibility.method == IncompressibilityMethod::augmentedLagrangian ? run.augmentation.get() : nullptr);
}

// What summary.json says of the run before its first step, and the console's first lines. The
// summary's kappa/mu figures are the Material section's tissue's (tissues[0]).
void describeRun(RunParts &run) {
  const model::Scene &scene = *run.scene;
  nlohmann::json &doc = run.report->doc();
  const Augmentation &augmentation = *run.augmentation;
  const double mu = augmentation.mu(0), kappaT = augmentation.tangentLaws()[0].kappa();
  const Teuchos::RCP<const Teuchos::Comm<int>> &solverComm = run.groups->groupComm();
  doc["linear_solver"] = run.linearPlan.description; // what Linear solver/type = auto chose
  if (run.control.enabled)
    doc["sensitivity_solve"] = run.linearPlan.directSensitivities ? "direct (MUMPS)" : run.linearPlan.description;
  for (const std::string &warning : ignoredIterativeSettings(run.config, run.linearPlan.direct,
                                                             run.assembler->layout().numGlobalDofs()))
    run.report->warn(warning);
  doc["deck"] = run.config.deckFile;
  doc["converged"] = false;
  doc["running"] = true;
  doc["ranks"] = run.comm->getSize();
  doc["control_groups"] = run.options.controlGroups;
  // The partition's balance (per rank of a control group).
  std::vector<double> mine(solverComm->getSize(), 0.0), all(mine.size(), 0.0);
  mine[solverComm->getRank()] = static_cast<double>(run.assembler->layout().numLocalElements());
  Teuchos::reduceAll(*solverComm, Teuchos::REDUCE_SUM, static_cast<int>(mine.size()), mine.data(), all.data());
  doc["elements_per_rank"] = all;
  doc["partitioner"] = scene.partitioner == model::Partitioner::coordinateBisection ? "coordinate bisection"
                       : scene.partitioner == model::Partitioner::zoltan2Rcb        ? "Zoltan2 RCB"
                                                                                     : "Zoltan2 multijagged";
  doc["dofs"] = run.assembler->layout().numGlobalDofs();
  doc["elements"] = scene.mesh.numElements();
  doc["incompressibility"] = methodName(run.config.incompressibility.method);
  doc["kappa_tangent"] = kappaT;
  doc["kappa_over_mu"] = kappaT / mu;
  doc["kappa_physical_over_mu"] = augmentation.physicalLaw(0).kappa() / mu; // inf is written as null
  doc["tissues"] = nlohmann::json::array();
  for (std::size_t t = 0; t < scene.tissues.size(); ++t) {
    const auto &tissue = scene.tissues[t];
    const auto elements = scene.elementTissue.empty()
                              ? scene.mesh.numElements()
                              : static_cast<std::size_t>(std::count(scene.elementTissue.begin(), scene.elementTissue.end(), static_cast<int>(t)));
    doc["tissues"].push_back({{"name", tissue.name}, {"elements", elements}, {"mu", tissue.matrix->shearModulus()},
                              {"kappa_physical", augmentation.physicalLaw(t).kappa()}, {"kappa_tangent", augmentation.tangentLaws()[t].kappa()},
                              {"density", tissue.density}});
  }
  if (run.uzawa->augmentedLagrangian())
    doc["kappa_AL_over_mu"] = Augmentation::augmentationKappa(run.config.incompressibility, mu) / mu;
  doc["steps"] = nlohmann::json::array();
  if (run.talk)
    std::printf("glossa: %s  %zu elements  %lld dofs  %d rank(s)  %s (kappa/mu = %.3g)\n", run.config.deckFile.c_str(),
                scene.mesh.numElements(), static_cast<long long>(run.assembler->layout().numGlobalDofs()),
                run.comm->getSize(), methodName(run.config.incompressibility.method), kappaT / mu);
  if (run.talk)
    for (const std::string &note : scene.meshNotes) std::printf("glossa: note: %s\n", note.c_str());
}

// Rank 0 holds the directory for the run's life before anything in it is cleared or written;
// every rank refuses alike when another run holds it.
void lockOutputDirectory(RunParts &run, const std::filesystem::path &dir) {
  int held = 1;
  std::string holder;
  if (run.root) {
    run.outputLock = std::make_unique<io::DirectoryLock>(dir);
    held = run.outputLock->held();
    holder = run.outputLock->holder();
  }
  Teuchos::broadcast(*run.comm, 0, &held);
  if (held) return;
  throw io::DeckError("the output directory " + dir.string() + " is in use by another glossa run" +
                      (holder.empty() ? std::string() : " (process " + holder + ")") +
                      ", which holds its lock file " + io::DirectoryLock::kFileName +
                      "; wait for that run to end, or give this one another directory (--output or Output/directory)");
}

// Where the results go: a new run's directory cleared of an earlier run's files, or a restart's
// with its checkpoint read (a bad deck has been refused before either).
std::filesystem::path outputDirectory(RunParts &run) {
  const RunOptions &options = run.options;
  std::filesystem::path dir =
      options.outputDirectory.empty() ? std::filesystem::path(run.config.output.directory) : options.outputDirectory;
  if (!options.restartDirectory.empty()) {
    if (!options.outputDirectory.empty())
      throw io::DeckError("--restart continues in the directory it names; leave out --output");
    dir = options.restartDirectory;
    run.restart = RunCheckpoint::read(dir, *run.comm, run.config.listing, options.controlGroups, checkpointShape(run));
  }
  lockOutputDirectory(run, dir);
  if (run.root && !run.restart) prepareOutputDirectory(dir);
  run.comm->barrier();
  return dir;
}
// Whether each step starts from the extrapolated state (Time/predictor). auto: not with the penalty
// method, whose kappa (5000 mu at nu = 0.4999) multiplies the volume error of an extrapolated
// displacement into its pressures (doc/theory.md, bench/README.md); nor under the GA, whose
// candidates start from its seed solve's state, not the step's start: there the extrapolation
// buys nothing on the coarse tongue and costs the medium one its seed (doc/control.md, "The GA's
// steps start from the committed state").
bool extrapolatesSteps(const RunParts &run) {
  const Predictor predictor = run.config.time.predictor;
  const bool underGa =
      run.control.enabled && run.control.parameters.type == control::ControllerType::geneticAlgorithm;
  return predictor == Predictor::linearExtrapolation ||
         (predictor == Predictor::automatic &&
          run.config.incompressibility.method != IncompressibilityMethod::penalty && !underGa);
}
} // namespace

std::unique_ptr<RunParts> setUpRun(const io::Deck &deck, const RunConfiguration &config,
                                   const Teuchos::RCP<const Teuchos::Comm<int>> &comm, const RunOptions &options) {
  auto run = std::make_unique<RunParts>();
  run->config = config;
  run->options = options;
  run->comm = comm;
  run->root = comm->getRank() == 0;
  run->talk = run->root && !options.quiet;
  run->detail = run->talk && options.verbose;
  run->report = std::make_unique<RunReport>(comm, run->root, run->talk);
  checkControlGroupCount(options.controlGroups, comm->getSize());
  buildScene(deck, *run);
  run->airway = input::buildAirway(deck, *run->scene);
  if (run->airway && run->airway->pressureLoad >= 0) {
    const model::FollowerPressureLoad &load = run->scene->pressures[static_cast<std::size_t>(run->airway->pressureLoad)];
    run->pcrit = std::make_unique<PcritSearch>(*run->airway, load.pressure, load.name);
  }
  if (run->scene->airflowLoad >= 0) // input::buildScene has refused an airflow without an airway
    run->airflow = std::make_unique<AirflowCoupling>(input::parseAirflowParameters(deck, run->config.time.rampEndTime),
                                                     run->airway, *run->scene);
  // Control groups: the world splits into G groups of equal size, each with its own copy of the
  // whole solver on a sub-communicator (every group steps the same committed state; GA
  // candidates are dealt out among the groups and the winner's state is broadcast).
  run->groups = std::make_unique<CommControlGroups>(comm, options.controlGroups);
  run->control = buildControl(deck, *run->scene);
  checkRunConfiguration(deck, run->config, *run->scene, run->control,
                        {comm->getSize(), options.controlGroups, !options.restartDirectory.empty()});
  buildSolvers(*run);

  const std::filesystem::path dir = outputDirectory(*run);
  run->report->setDirectory(dir);
  const OutputParameters &output = run->config.output;
  run->report->recordingOutputFailure([&] {
    run->recorder = std::make_unique<StepRecorder>(assembly::ResultEvaluator(*run->assembler), dir, output.fields, run->root,
                                                   output.resultantFaceSets, output.volumeFaceSets,
                                                   run->restart ? &run->restart->outputs : nullptr,
                                                   run->config.time.dynamics.dynamic(), run->airway);
  });
  // None on an arc-length path (its direction and step are LOCA's own state).
  run->checkpoints = std::make_unique<RunCheckpoint>(dir, comm, output.checkpointEvery);
  describeRun(*run);

  run->stepper = std::make_unique<LoadStepper>(
      run->config.time.steps, extrapolatesSteps(*run),
      StepState(run->assembler->layout().ownedMap(), run->assembler->layout().numLocalElements()));
  if (run->config.time.dynamics.dynamic()) {
    run->inertia = std::make_unique<Inertia>(*run->assembler, run->config.time.dynamics, run->stepper->committed());
    run->model->setInertia(run->inertia.get());
    run->recorder->showInertia(run->inertia.get());
  }
  if (run->control.enabled) {
    // The sensitivity tangent (ControllerParameters::sensitivityTangent) of the gradient
    // controller's sensitivities and of the responses the GA's candidates start along: the
    // constrained one costs MueLu more Krylov iterations than it saves (doc/control.md), and a
    // factorisation nothing more.
    const control::ControllerParameters &cp = run->control.parameters;
    const bool augmented = run->config.incompressibility.method == IncompressibilityMethod::augmentedLagrangian;
    const bool constrainedSensitivity =
        augmented && (cp.sensitivityTangent == control::SensitivityTangent::constrained ||
         (cp.sensitivityTangent == control::SensitivityTangent::automatic && run->linearPlan.directSensitivities));
    std::optional<std::uintmax_t> resumeAt;
    if (run->restart && run->restart->outputs.csvBytes.count("controls.csv"))
      resumeAt = run->restart->outputs.csvBytes.at("controls.csv");
    run->report->recordingOutputFailure([&] { // controls.csv
      run->controlled = std::make_unique<ControlledSteps>(run->control, run->stepSolverParts(), *run->solver,
                                                          *run->stepper, *run->groups, dir, resumeAt, run->root, run->detail,
                                                          run->airway,
                                                          augmented ? run->augmentation.get() : nullptr,
                                                          constrainedSensitivity);
    });
  }
  return run;
}

} // namespace glossa::solvers
