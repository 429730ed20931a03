#include "solvers/Simulation.hpp"

#include <chrono>
#include <map>
#include <cstdio>
#include <iostream>
#include <sys/resource.h>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include "assembly/Assembler.hpp"
#include "assembly/ModelEvaluator.hpp"
#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "io/output/KeyedCsvWriter.hpp"
#include "io/output/ResultWriter.hpp"
#include "io/output/SummaryWriter.hpp"
#include "io/output/TraceWriter.hpp"
#include "model/SceneFactory.hpp"
#include "control/ControlObjective.hpp"
#include "control/ElitistGeneticAlgorithm.hpp"
#include "control/MusclePruning.hpp"
#include "control/GaussNewtonController.hpp"
#include "solvers/ControlSection.hpp"
#include "solvers/ControlSensitivity.hpp"
#include "solvers/LinearSolverFactory.hpp"
#include "solvers/NewtonSolver.hpp"
#include "solvers/StepRecorder.hpp"
#include "solvers/TimeStepping.hpp"
#include "solvers/MixedBlockSolver.hpp"
#include "solvers/UzawaLoop.hpp"

namespace glossa::solvers {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

Teuchos::ParameterList outputParameters() {
  Teuchos::ParameterList p;
  io::declareString(p, "directory", "results", "where results go (glossa run --output overrides)");
  io::declareInt(p, "every", 1, "write fields every this many converged steps (the last always)",
                 io::Range::atLeast(1));
  io::declareBool(p, "fields", true, "write HDF5/XDMF fields (traces and summary are always written)");
  return p;
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
void requireMixedCompatible(const Teuchos::ParameterList &D, const model::Scene &scene) {
  const std::string why = "Incompressibility/method = mixed needs ";
  if (scene.formulation != model::ElementFormulation::Q1P0) throw io::DeckError(why + "Material/element = Q1P0");
  if (D.sublist("Nonlinear solver").get<std::string>("line search") != "full step")
    throw io::DeckError(why + "Nonlinear solver/line search = full step (its pressure increment is not line-searched)");
  if (D.sublist("Linear solver").get<std::string>("type") != "iterative")
    throw io::DeckError(why + "Linear solver/type = iterative (the block system is solved by GMRES)");
  if (D.sublist("Control").get<std::string>("type") != "none")
    throw io::DeckError(why + "Control/type = none (the controllers' sensitivities use the condensed tangent)");
}
} // namespace

nlohmann::json runSimulation(const io::Deck &deck, const Teuchos::RCP<const Teuchos::Comm<int>> &comm,
                             const RunOptions &options) {
  const auto start = Clock::now();
  const double setupAtStart = timerSeconds("NOX Total Preconditioner Construction");
  const double solveAtStart = timerSeconds("NOX Total Linear Solve");
  const bool root = comm->getRank() == 0;
  const bool talk = root && !options.quiet;
  const auto &D = deck.root();

  StepSizeController steps(D.sublist("Time"));
  model::Scene scene = model::buildScene(deck, steps.endTime());
  const double mu = scene.material->shearModulus();
  const auto &incompressibility = D.sublist("Incompressibility");
  // The material's law stays the physical one for the Uzawa loop; the tangent gets kappa_t.
  const materials::VolumetricEnergy physicalVolumetric = scene.volumetric;
  scene.volumetric = scene.volumetric.withKappa(UzawaLoop::tangentKappa(incompressibility, scene.volumetric.kappa(), mu));

  // Control groups: the world splits into G groups of equal size, each with its own copy of
  // the whole solver on a sub-communicator (every group steps the same committed state; GA
  // candidates are dealt out among the groups and the winner's state is broadcast).
  const int controlGroups = options.controlGroups;
  if (controlGroups < 1 || comm->getSize() % controlGroups != 0)
    throw io::DeckError("--control-groups " + std::to_string(controlGroups) +
                                " must be at least 1 and divide the number of ranks (" +
                                std::to_string(comm->getSize()) + ")");
  const int groupSize = comm->getSize() / controlGroups;
  const int myGroup = comm->getRank() / groupSize;
  const Teuchos::RCP<const Teuchos::Comm<int>> solverComm =
      controlGroups == 1 ? comm : Teuchos::RCP<const Teuchos::Comm<int>>(comm->split(myGroup, comm->getRank()));
  const bool groupRoot = solverComm->getRank() == 0;

  auto assembler = Teuchos::rcp(new assembly::Assembler(scene, solverComm));
  LinearSolverContext context{assembler->coordinates(), assembler->rigidBodyModes(), solverComm->getSize(),
                              assembler->layout().numGlobalDofs(), scene.symmetricTangent};
  const auto &linearSection = D.sublist("Linear solver");
  Teuchos::RCP<assembly::MixedPressureState> mixedPressure;
  if (incompressibility.get<std::string>("method") == "mixed") {
    requireMixedCompatible(D, scene);
    const AugmentedLagrangianRule law(physicalVolumetric, mu); // only its theta_phys(p) is used
    mixedPressure = Teuchos::rcp(new assembly::MixedPressureState(
        physicalVolumetric, [law](double p) { return law.dilatationAtPressure(p); }, mu));
  }
  auto model = Teuchos::rcp(new assembly::ModelEvaluator(
      assembler, mixedPressure.is_null() ? buildLinearSolver(linearSection, context)
                                         : buildMixedBlockSolver(linearSection, context, mixedPressure)));
  model->setMixedPressure(mixedPressure);
  double lengthScale = 0.0;
  for (const auto &x : scene.mesh.nodes) lengthScale = std::max(lengthScale, x.norm());
  NewtonSolver newton(model, D.sublist("Nonlinear solver"), lengthScale, linearSection.get<double>("tolerance"),
                      linearSection.get<std::string>("MueLu reuse scope") == "run");
  UzawaLoop uzawa(*assembler, newton, incompressibility, physicalVolumetric, mu);

  std::filesystem::path dir = options.outputDirectory.empty()
                                  ? std::filesystem::path(D.sublist("Output").get<std::string>("directory"))
                                  : options.outputDirectory;
  if (root) std::filesystem::create_directories(dir);
  comm->barrier();
  StepRecorder recorder(*assembler, dir, D.sublist("Output").get<bool>("fields"), root);
  const int every = D.sublist("Output").get<int>("every");

  std::unique_ptr<io::SummaryWriter> summary;
  nlohmann::json doc;
  doc["deck"] = deck.file();
  doc["converged"] = false;
  doc["running"] = true;
  doc["ranks"] = comm->getSize();
  doc["control_groups"] = controlGroups;
  {
    // The partition's balance (per rank of a control group).
    std::vector<double> mine(solverComm->getSize(), 0.0), all(mine.size(), 0.0);
    mine[solverComm->getRank()] = static_cast<double>(assembler->numLocalElements());
    Teuchos::reduceAll(*solverComm, Teuchos::REDUCE_SUM, static_cast<int>(mine.size()), mine.data(), all.data());
    doc["elements_per_rank"] = all;
    doc["partitioner"] = scene.partitioner == model::Partitioner::coordinateBisection ? "coordinate bisection"
                         : scene.partitioner == model::Partitioner::zoltan2Rcb        ? "Zoltan2 RCB"
                                                                                       : "Zoltan2 multijagged";
  }
  doc["dofs"] = assembler->layout().numGlobalDofs();
  doc["elements"] = scene.mesh.numElements();
  doc["incompressibility"] = incompressibility.get<std::string>("method");
  doc["kappa_tangent"] = scene.volumetric.kappa();
  doc["kappa_over_mu"] = scene.volumetric.kappa() / mu;
  doc["kappa_physical_over_mu"] = physicalVolumetric.kappa() / mu; // inf is written as null
  if (uzawa.augmentedLagrangian()) doc["kappa_AL_over_mu"] = UzawaLoop::augmentationKappa(incompressibility, mu) / mu;
  doc["steps"] = nlohmann::json::array();
  auto writeSummary = [&] {
    doc["wall_seconds"] = since(start);
    doc["assembly_seconds"] = model->assemblySeconds();
    // NOX's own timers split the linear solves into preconditioner set-up and Krylov iterations.
    doc["preconditioner_setup_seconds"] = timerSeconds("NOX Total Preconditioner Construction") - setupAtStart;
    doc["linear_solve_seconds"] = timerSeconds("NOX Total Linear Solve") - solveAtStart;
    double peak = peakMemoryMegabytes(), peakMax = 0.0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, peak, Teuchos::outArg(peakMax));
    doc["peak_memory_mb_per_rank"] = peakMax;
    if (!root) return;
    if (!summary) summary = std::make_unique<io::SummaryWriter>(dir / "summary.json");
    summary->root() = doc;
    summary->write();
  };

  if (talk)
    std::printf("glossa: %s  %zu elements  %lld dofs  %d rank(s)  %s (kappa/mu = %.3g)\n", deck.file().c_str(),
                scene.mesh.numElements(), static_cast<long long>(assembler->layout().numGlobalDofs()),
                comm->getSize(), incompressibility.get<std::string>("method").c_str(), scene.volumetric.kappa() / mu);

  assembly::Vector u(assembler->ownedMap());
  std::vector<double> lambda(assembler->numLocalElements(), 0.0);
  model::MuscleHistory &history = assembler->muscleHistory();
  auto inputs = [&](double time) {
    std::vector<double> v;
    for (std::size_t g = 0; g < scene.muscles.groups.size(); ++g) v.push_back(history.input(static_cast<int>(g), time));
    return v;
  };
  const assembly::MuscleFields initialMuscle = assembler->updateMuscleHistory(u);
  recorder.record(0.0, u, lambda, true, initialMuscle, inputs(0.0));
  writeSummary();

  // One step from the committed state to tNew: u and lambda hold the committed state on entry
  // and the trial state on return; the muscle history's trial values are this step's. Nothing is
  // committed here, so a controller may attempt many inputs from one state.
  struct StepAttempt {
    UzawaResult uzawa;
    assembly::MuscleFields muscle;
    bool ok = false;
    std::string why;
  };
  bool inCandidate = false; // a controller's candidate solve: no per-iteration progress
  auto attemptStep = [&](double tNew, double dt, assembly::Vector &uTrial, std::vector<double> &lambdaTrial) {
    StepAttempt out;
    assembler->applyDirichlet(uTrial, tNew);
    model->setTime(tNew);
    model->setLambda(&lambdaTrial);
    history.beginStep(tNew, dt); // trial activation; lambda_c stays at its committed value

    // The Newton tolerance scales with the load: the external force and the step's initial residual.
    assembly::Vector f0(assembler->ownedMap());
    std::vector<double> lambdaNow = lambdaTrial;
    assembler->assemble(uTrial, tNew, lambdaNow, nullptr, &f0, nullptr);
    double reference = std::max(assembler->externalForceNorm(tNew), f0.norm2());
    if (!(reference > 0.0)) reference = 1.0;
    const double tolerance = newton.relativeResidualTolerance() * reference;

    auto onNewton = [&](int k, double normF, int krylov) {
      if (talk && !inCandidate) std::printf("    newton %2d  |f| = %.3e  krylov %d\n", k, normF, krylov);
    };
    auto onUzawa = [&](int k, const NewtonResult &n, const DilatationError &e) {
      if (talk && !inCandidate)
        std::printf("  uzawa %d: newton %d  krylov %d  dilatation error max %.2e  mean %.2e  max|theta-1| %.2e\n", k,
                    n.iterations, n.linearIterations, e.max, e.mean, e.maxVolumeChange);
    };
    out.uzawa = uzawa.solve(uTrial, lambdaTrial, tolerance, onNewton, onUzawa);
    model->setLambda(nullptr);
    // The history at the converged state: lambda_c of every point with this step's activation.
    if (out.uzawa.converged) out.muscle = assembler->updateMuscleHistory(uTrial);
    out.ok = out.uzawa.converged && out.muscle.valid;
    if (!out.ok) {
      const UzawaResult &r = out.uzawa;
      const NewtonResult &last = r.newton.back();
      out.why = !out.muscle.valid ? "a contractile-stretch solve failed at the converged state"
                : r.elementInverted ? "an element inverted (J <= 0) or a muscle point law failed"
                : !last.failure.empty() ? last.failure.substr(0, last.failure.find('\n'))
                : !last.converged ? "Newton did not converge"
                                  : "Uzawa did not reach the dilatation tolerance";
    }
    return out;
  };

  // Neural control (issue 5): per step, the elitist GA picks the inputs of the controlled groups
  // that keep the control points at their reference positions (eq. 25), each candidate a full
  // step solve from the committed state; the winner's state is committed.
  const ControlSetup control = buildControl(deck, scene);
  if (controlGroups > 1 && !(control.enabled && control.parameters.type == control::ControllerType::geneticAlgorithm))
    throw io::DeckError("--control-groups " + std::to_string(controlGroups) +
                                " needs Control/type = genetic algorithm (the candidates it shares out)");
  std::unique_ptr<io::KeyedCsvWriter> controls;
  if (control.enabled && root)
    controls = std::make_unique<io::KeyedCsvWriter>(
        dir / "controls.csv", "group", std::vector<std::string>{"u", "evaluated", "objective", "candidates"});
  std::vector<double> committedStretch = initialMuscle.groupMeanStretch; // for pruning
  control::Genome previousBest;
  struct ControlOutcome {
    std::vector<double> inputs;
    std::vector<int> evaluated;
    double objective = 0.0;
    std::size_t candidates = 0;
    int generations = 0;      // GA
    int iterations = 0;       // gradient: accepted Gauss-Newton steps
    int sensitivities = 0;    // gradient: sensitivity evaluations
    int sensitivityKrylov = 0; // gradient: their Krylov iterations
    double sensitivityCheck = -1.0; // verify sensitivities: max |S - S_fd| / max |S_fd| (-1: not checked)
    std::string stop;
    Eigen::VectorXd pointErrors;
  };
  // Control groups: every group holds its own best candidate; the world's winner is the one with
  // the least rank, the earliest evaluated among equals (the single-group rule), and its root
  // broadcasts the winner's inputs, state and solve statistics to every rank.
  auto shareWinner = [&](double &best, double &bestRank, long &bestIndex, std::vector<double> &bestInputs,
                         assembly::Vector &uBest, std::vector<double> &lambdaBest, StepAttempt &attemptBest,
                         Eigen::VectorXd &bestErrors, const control::ControlObjective &objective) {
    std::vector<double> ranks(controlGroups, 0.0), indices(controlGroups, 0.0), all(controlGroups);
    if (groupRoot) {
      ranks[myGroup] = bestRank;
      indices[myGroup] = static_cast<double>(bestIndex);
    }
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, controlGroups, ranks.data(), all.data());
    ranks = all;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, controlGroups, indices.data(), all.data());
    indices = all;
    int winner = 0;
    for (int c = 1; c < controlGroups; ++c)
      if (ranks[c] < ranks[winner] || (ranks[c] == ranks[winner] && indices[c] < indices[winner])) winner = c;
    if (!std::isfinite(ranks[winner])) { // no candidate converged anywhere
      best = bestRank = std::numeric_limits<double>::infinity();
      return;
    }
    // Pack: [best, rank, index, inputs..., u (all nodes)..., lambda (all elements)..., the solve's
    // statistics and Newton histories].
    std::vector<double> pack;
    if (myGroup == winner) {
      const std::vector<double> uAll = assembler->gatherDisplacement(uBest);
      const std::vector<double> lambdaAll = assembler->gatherElementField(lambdaBest, 1);
      const UzawaResult &r = attemptBest.uzawa;
      pack = {best, bestRank, static_cast<double>(bestIndex)};
      pack.insert(pack.end(), bestInputs.begin(), bestInputs.end());
      pack.insert(pack.end(), uAll.begin(), uAll.end());
      pack.insert(pack.end(), lambdaAll.begin(), lambdaAll.end());
      for (double v : {double(r.converged), double(r.elementInverted), double(r.solves), double(r.newtonIterations),
                       double(r.linearIterations), r.dilatation.max, r.dilatation.mean, r.dilatation.maxVolumeChange,
                       double(r.newton.size())})
        pack.push_back(v);
      for (const auto &n : r.newton) {
        for (double v : {double(n.converged), double(n.iterations), double(n.linearIterations),
                         double(n.residualNorms.size()), double(n.linearIterationsPerStep.size())})
          pack.push_back(v);
        pack.insert(pack.end(), n.residualNorms.begin(), n.residualNorms.end());
        pack.insert(pack.end(), n.linearIterationsPerStep.begin(), n.linearIterationsPerStep.end());
      }
    }
    const int from = winner * groupSize;
    int size = static_cast<int>(pack.size());
    Teuchos::broadcast(*comm, from, Teuchos::outArg(size));
    pack.resize(static_cast<std::size_t>(size));
    Teuchos::broadcast(*comm, from, size, pack.data());
    std::size_t k = 0;
    auto take = [&](std::size_t n) {
      std::vector<double> v(pack.begin() + static_cast<long>(k), pack.begin() + static_cast<long>(k + n));
      k += n;
      return v;
    };
    best = pack[0];
    bestRank = pack[1];
    bestIndex = static_cast<long>(pack[2]);
    k = 3;
    bestInputs = take(scene.muscles.groups.size());
    const std::vector<double> uAll = take(3 * scene.mesh.numNodes());
    assembler->scatterDisplacement(uAll, uBest);
    lambdaBest = assembler->localElementValues(take(scene.mesh.numElements()));
    UzawaResult r;
    const auto head = take(9);
    r.converged = head[0] != 0.0;
    r.elementInverted = head[1] != 0.0;
    r.solves = static_cast<int>(head[2]);
    r.newtonIterations = static_cast<int>(head[3]);
    r.linearIterations = static_cast<int>(head[4]);
    r.dilatation = {head[5], head[6], head[7]};
    for (int i = 0; i < static_cast<int>(head[8]); ++i) {
      const auto h = take(5);
      NewtonResult n;
      n.converged = h[0] != 0.0;
      n.iterations = static_cast<int>(h[1]);
      n.linearIterations = static_cast<int>(h[2]);
      n.residualNorms = take(static_cast<std::size_t>(h[3]));
      for (double v : take(static_cast<std::size_t>(h[4]))) n.linearIterationsPerStep.push_back(static_cast<int>(v));
      r.newton.push_back(n);
    }
    attemptBest = StepAttempt{};
    attemptBest.uzawa = r;
    attemptBest.ok = true;
    Eigen::Matrix3Xd x(3, control.pointNodes.size());
    for (std::size_t p = 0; p < control.pointNodes.size(); ++p) {
      const auto n = control.pointNodes[p];
      x.col(p) = scene.mesh.nodes[n] + Eigen::Vector3d(uAll[3 * n], uAll[3 * n + 1], uAll[3 * n + 2]);
    }
    bestErrors = objective.evaluate(x).distance;
  };
  auto controlledStep = [&](int stepIndex, double tNew, double dt, assembly::Vector &uTrial,
                            std::vector<double> &lambdaTrial, StepAttempt &attempt, ControlOutcome &outcome) {
    const std::size_t G = scene.muscles.groups.size();
    // Pruning: the controlled groups whose mean fibre stretch at the committed state exceeds its
    // reference value (1: no pre-strain), plus those always evaluated and (by default) those the
    // previous step switched on.
    std::vector<double> stretch, reference;
    std::vector<bool> always;
    std::vector<std::string> names;
    for (const auto &g : scene.muscles.groups) names.push_back(g.name);
    const auto alwaysMask = control.parameters.alwaysEvaluatedMask(names);
    for (std::size_t i = 0; i < control.groups.size(); ++i) {
      const int g = control.groups[i];
      stretch.push_back(committedStretch[g]);
      reference.push_back(1.0);
      const bool active = control.parameters.keepActiveGroups && i < previousBest.size() && previousBest[i] > 0.0;
      always.push_back(alwaysMask[g] || active);
    }
    std::vector<int> local = control.parameters.pruning
                                 ? control::groupsInTension(stretch, reference, control.parameters.pruningTolerance, always)
                                 : std::vector<int>();
    if (!control.parameters.pruning)
      for (std::size_t i = 0; i < control.groups.size(); ++i) local.push_back(static_cast<int>(i));
    std::vector<int> evaluated;
    for (int i : local) evaluated.push_back(control.groups[i]);
    outcome.evaluated = evaluated;

    const Eigen::Matrix3Xd &goal = control.goals;
    const control::ControlObjective objective(goal, control.weights);
    // Every candidate is a full step solve from the committed state. The first candidate to beat
    // every earlier one by `rank` (the GA: eq. 25; the gradient controller: the sum of squares it
    // minimises) keeps its state, so the winner's state is at hand when the search ends.
    double best = std::numeric_limits<double>::infinity(), bestRank = best;
    long bestIndex = -1; // the winner's position in the order of evaluation (control groups)
    std::vector<double> bestInputs;
    assembly::Vector uBest(u, Teuchos::Copy);
    std::vector<double> lambdaBest;
    StepAttempt attemptBest;
    Eigen::VectorXd bestErrors;
    auto apply = [&](const std::vector<double> &inputs) {
      for (std::size_t g = 0; g < G; ++g)
        if (std::find(control.groups.begin(), control.groups.end(), static_cast<int>(g)) != control.groups.end())
          history.overrideInput(static_cast<int>(g), inputs[g]);
    };
    auto solveCandidate = [&](const std::vector<double> &inputs, bool rankByObjective, long index) {
      apply(inputs);
      assembly::Vector uC(u, Teuchos::Copy);
      std::vector<double> lambdaC = lambda;
      inCandidate = true;
      StepAttempt a = attemptStep(tNew, dt, uC, lambdaC);
      inCandidate = false;
      control::ControlEvaluation e;
      e.objective = std::numeric_limits<double>::infinity();
      Eigen::VectorXd errors;
      if (a.ok) {
        const std::vector<double> all = assembler->gatherDisplacement(uC);
        Eigen::Matrix3Xd x(3, control.pointNodes.size());
        for (std::size_t p = 0; p < control.pointNodes.size(); ++p) {
          const auto n = control.pointNodes[p];
          x.col(p) = scene.mesh.nodes[n] + Eigen::Vector3d(all[3 * n], all[3 * n + 1], all[3 * n + 2]);
        }
        const auto v = objective.evaluate(x);
        e.ok = true;
        e.objective = v.total;
        const Eigen::Matrix3Xd offset = x - goal;
        e.residual = Eigen::Map<const Eigen::VectorXd>(offset.data(), offset.size());
        for (Eigen::Index p = 0; p < x.cols(); ++p) e.residual.segment<3>(3 * p) *= control.weights(p);
        errors = v.distance;
      }
      const double rank = !e.ok ? e.objective : rankByObjective ? e.objective : e.residual.squaredNorm();
      if (rank < bestRank) {
        bestRank = rank;
        bestIndex = index;
        best = e.objective;
        bestInputs = inputs;
        uBest.assign(uC);
        lambdaBest = lambdaC;
        attemptBest = a;
        bestErrors = errors;
      }
      return e;
    };
    std::vector<double> previousInputs(G, 0.0);
    for (std::size_t i = 0; i < control.groups.size() && i < previousBest.size(); ++i)
      previousInputs[control.groups[i]] = previousBest[i];
    if (control.parameters.type == control::ControllerType::geneticAlgorithm) {
      long evaluatedSoFar = 0;
      auto evaluate = [&](const std::vector<control::Genome> &genomes) {
        // Candidate i of the batch is solved by control group i mod G; the objectives are summed
        // over the world from each group's root (every other entry 0), so all ranks see all.
        std::vector<double> values(genomes.size(), 0.0);
        for (std::size_t i = 0; i < genomes.size(); ++i)
          if (static_cast<int>(i % static_cast<std::size_t>(controlGroups)) == myGroup)
            values[i] = solveCandidate(control::inputsFromGenome(evaluated, genomes[i], G), true,
                                       evaluatedSoFar + static_cast<long>(i))
                            .objective;
        evaluatedSoFar += static_cast<long>(genomes.size());
        if (controlGroups == 1) return values;
        if (!groupRoot) std::fill(values.begin(), values.end(), 0.0);
        std::vector<double> all(values.size(), 0.0);
        Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, static_cast<int>(values.size()), values.data(), all.data());
        return all;
      };
      control::GeneticAlgorithmParameters gaParameters = control.parameters.ga;
      gaParameters.seed += static_cast<std::uint64_t>(stepIndex); // fresh draws per control step
      const control::ElitistGeneticAlgorithm ga(gaParameters);
      std::vector<control::Genome> seeds;
      if (control.parameters.seedWithPreviousBest && !previousBest.empty())
        seeds.push_back(control::genomeFromInputs(evaluated, previousInputs));
      const auto result = ga.minimise(evaluated.size(), evaluate, seeds);
      if (controlGroups > 1) shareWinner(best, bestRank, bestIndex, bestInputs, uBest, lambdaBest, attemptBest, bestErrors, objective);
      outcome.candidates = result.evaluations;
      outcome.generations = result.generations;
      outcome.stop = control::toString(result.stopReason);
    } else {
      // Projected Gauss-Newton from the previous step's inputs, on the evaluated groups.
      auto inputsOf = [&](const Eigen::VectorXd &v) {
        std::vector<double> inputs(G, 0.0);
        for (std::size_t i = 0; i < evaluated.size(); ++i) inputs[evaluated[i]] = v(static_cast<Eigen::Index>(i));
        return inputs;
      };
      long evaluatedSoFar = 0;
      auto evaluate = [&](const Eigen::VectorXd &v) { return solveCandidate(inputsOf(v), false, evaluatedSoFar++); };
      auto sensitivity = [&](const Eigen::VectorXd &v) {
        if (inputsOf(v) != bestInputs)
          throw std::logic_error("gradient controller: sensitivity asked away from the accepted state");
        apply(bestInputs);
        history.beginStep(tNew, dt);
        model->setTime(tNew);
        model->setLambda(&lambdaBest);
        const auto s = controlPointSensitivity(*assembler, newton, uBest, lambdaBest, tNew, evaluated, control.pointNodes);
        model->setLambda(nullptr);
        outcome.sensitivityKrylov += s.krylovIterations;
        if (control.parameters.verifySensitivities) {
          // Central differences of full step solves (second-order one-sided at the bounds of [0, 1]).
          constexpr double h = 1e-3;
          auto pointsAt = [&](const std::vector<double> &inputs) {
            apply(inputs);
            assembly::Vector uC(u, Teuchos::Copy);
            std::vector<double> lambdaC = lambda;
            inCandidate = true;
            const StepAttempt a = attemptStep(tNew, dt, uC, lambdaC);
            inCandidate = false;
            if (!a.ok) throw std::runtime_error("verify sensitivities: a differenced solve failed: " + a.why);
            const std::vector<double> all = assembler->gatherDisplacement(uC);
            Eigen::VectorXd x(3 * static_cast<Eigen::Index>(control.pointNodes.size()));
            for (std::size_t p = 0; p < control.pointNodes.size(); ++p)
              for (int c = 0; c < 3; ++c) x(3 * static_cast<Eigen::Index>(p) + c) = all[3 * control.pointNodes[p] + c];
            return x;
          };
          Eigen::MatrixXd fd(s.dxdu.rows(), s.dxdu.cols());
          for (std::size_t j = 0; j < evaluated.size(); ++j) {
            const int g = evaluated[j];
            auto at = [&](double du) {
              std::vector<double> inputs = bestInputs;
              inputs[g] += du;
              return pointsAt(inputs);
            };
            const double ug = bestInputs[g];
            const auto col = static_cast<Eigen::Index>(j);
            if (ug - h >= 0.0 && ug + h <= 1.0) fd.col(col) = (at(h) - at(-h)) / (2.0 * h);
            else {
              const double s = ug - h < 0.0 ? h : -h; // second-order one-sided, inside [0, 1]
              fd.col(col) = (-3.0 * at(0.0) + 4.0 * at(s) - at(2.0 * s)) / (2.0 * s);
            }
          }
          const double scale = fd.cwiseAbs().maxCoeff();
          if (scale > 0.0)
            outcome.sensitivityCheck = std::max(outcome.sensitivityCheck, (s.dxdu - fd).cwiseAbs().maxCoeff() / scale);
          if (talk)
            std::printf("  sensitivity check: max |S - S_fd| / max |S_fd| = %.3e\n", outcome.sensitivityCheck);
        }
        Eigen::MatrixXd S = s.dxdu;
        for (Eigen::Index p = 0; p < static_cast<Eigen::Index>(control.pointNodes.size()); ++p)
          S.middleRows<3>(3 * p) *= control.weights(p);
        return S;
      };
      Eigen::VectorXd start(static_cast<Eigen::Index>(evaluated.size()));
      for (std::size_t i = 0; i < evaluated.size(); ++i) start(static_cast<Eigen::Index>(i)) = previousInputs[evaluated[i]];
      const control::GaussNewtonController controller(control.parameters.gradient);
      const auto result = controller.minimise(start, evaluate, sensitivity);
      outcome.candidates = static_cast<std::size_t>(result.evaluations);
      outcome.iterations = result.iterations;
      outcome.sensitivities = result.sensitivities;
      outcome.stop = control::toString(result.stop);
    }
    outcome.objective = best;
    outcome.pointErrors = bestErrors;
    if (!std::isfinite(best)) {
      attempt = attemptBest;
      attempt.ok = false;
      attempt.why = "no candidate input converged";
      return;
    }
    // The winner's trial history (activation and lambda_c at its converged state), then its state.
    apply(bestInputs);
    history.beginStep(tNew, dt);
    attemptBest.muscle = assembler->updateMuscleHistory(uBest);
    uTrial.assign(uBest);
    lambdaTrial = lambdaBest;
    attempt = attemptBest;
    outcome.inputs = bestInputs;
    previousBest.assign(control.groups.size(), 0.0);
    for (std::size_t i = 0; i < control.groups.size(); ++i) previousBest[i] = bestInputs[control.groups[i]];
  };

  double t = 0.0;
  int stepNumber = 0, converged = 1;
  std::string failure;
  while (t < steps.endTime() * (1.0 - 1e-12)) {
    const double dt = steps.nextStep(t);
    const double tNew = t + dt;
    const auto stepStart = Clock::now();
    const double solveStart = model->assemblySeconds();
    assembly::Vector uTrial(u, Teuchos::Copy);
    std::vector<double> lambdaTrial = lambda;
    if (talk) std::printf("step %d  t = %.6g  dt = %.3g\n", stepNumber + 1, tNew, dt);
    StepAttempt attempt;
    ControlOutcome outcome;
    if (control.enabled) controlledStep(stepNumber, tNew, dt, uTrial, lambdaTrial, attempt, outcome);
    else attempt = attemptStep(tNew, dt, uTrial, lambdaTrial);
    UzawaResult &r = attempt.uzawa;
    assembly::MuscleFields &muscle = attempt.muscle;
    if (!attempt.ok) {
      const std::string &why = attempt.why;
      if (talk) std::printf("  step failed at t = %.6g: %s; cutting back\n", tNew, why.c_str());
      if (!steps.cutBack()) {
        failure = "step to t = " + std::to_string(tNew) + " failed (" + why + ") below the minimum step size";
        converged = 0;
        break;
      }
      continue;
    }
    // Commit (the muscle history after the output, whose stresses are those of the converged
    // state: this step's activation with the committed lambda_c it was solved with).
    u.assign(uTrial);
    lambda = lambdaTrial;
    t = tNew;
    ++stepNumber;
    steps.accept();
    const bool last = t >= steps.endTime() * (1.0 - 1e-12);
    const auto reactions = recorder.record(t, u, lambda, last || stepNumber % every == 0, muscle, history.trialInput());

    nlohmann::json step;
    step["time"] = t;
    step["dt"] = dt;
    step["newton_iterations"] = r.newtonIterations;
    step["linear_iterations"] = r.linearIterations;
    step["uzawa_iterations"] = r.solves;
    step["max_dilatation_error"] = r.dilatation.max;
    step["mean_dilatation_error"] = r.dilatation.mean;
    step["max_volume_change"] = r.dilatation.maxVolumeChange;
    step["seconds"] = since(stepStart);
    step["assembly_seconds"] = model->assemblySeconds() - solveStart;
    nlohmann::json histories = nlohmann::json::array();
    for (const auto &n : r.newton) histories.push_back({{"residual_norms", n.residualNorms}, {"krylov", n.linearIterationsPerStep}});
    step["newton_solves"] = histories;
    nlohmann::json reactionJson = nlohmann::json::object();
    for (const auto &[name, force] : reactions) reactionJson[name] = force;
    step["reactions"] = reactionJson;
    if (!scene.muscles.groups.empty()) {
      nlohmann::json activation = nlohmann::json::object();
      for (const auto &[group, values] : recorder.activationRows(muscle, history.trialInput()))
        activation[group] = {{"u", values[0]}, {"alpha", values[1]}, {"ffmr", values[2]}, {"mean_fibre_stretch", values[3]},
                             {"mean_contractile_stretch", values[4]}};
      step["activation"] = activation;
    }
    if (control.enabled) {
      nlohmann::json c;
      c["objective"] = outcome.objective;
      c["candidates"] = outcome.candidates;
      if (control.parameters.type == control::ControllerType::geneticAlgorithm) {
        c["generations"] = outcome.generations;
      } else {
        c["iterations"] = outcome.iterations;
        c["sensitivity_evaluations"] = outcome.sensitivities;
        c["sensitivity_krylov"] = outcome.sensitivityKrylov;
        if (outcome.sensitivityCheck >= 0.0) c["sensitivity_check"] = outcome.sensitivityCheck;
      }
      c["stop"] = outcome.stop;
      nlohmann::json inputs = nlohmann::json::object(), errors = nlohmann::json::object();
      std::vector<std::pair<std::string, std::vector<double>>> rows;
      for (int g : control.groups) {
        const bool evaluated = std::find(outcome.evaluated.begin(), outcome.evaluated.end(), g) != outcome.evaluated.end();
        inputs[scene.muscles.groups[g].name] = outcome.inputs[g];
        rows.push_back({scene.muscles.groups[g].name,
                        {outcome.inputs[g], evaluated ? 1.0 : 0.0, outcome.objective, static_cast<double>(outcome.candidates)}});
      }
      for (std::size_t p = 0; p < control.pointNames.size(); ++p)
        errors[control.pointNames[p]] = outcome.pointErrors(static_cast<Eigen::Index>(p));
      c["inputs"] = inputs;
      c["point_errors"] = errors;
      step["control"] = c;
      if (controls) controls->append(t, rows);
      if (talk)
        std::printf("  control: objective %.3e  candidates %zu  %s %d (%s)\n", outcome.objective, outcome.candidates,
                    control.parameters.type == control::ControllerType::geneticAlgorithm ? "generations" : "iterations",
                    control.parameters.type == control::ControllerType::geneticAlgorithm ? outcome.generations
                                                                                         : outcome.iterations,
                    outcome.stop.c_str());
    }
    doc["steps"].push_back(step);
    committedStretch = muscle.groupMeanStretch;
    history.commit();
    if (talk)
      std::printf("step %d done  t = %.6g  newton %d  krylov %d  uzawa %d  dilatation error %.2e  [%.2f s]\n", stepNumber,
                  t, r.newtonIterations, r.linearIterations, r.solves, r.dilatation.max, since(start));
    writeSummary();
  }

  const std::vector<double> uAll = assembler->gatherDisplacement(u);
  if (options.finalDisplacement) *options.finalDisplacement = uAll;
  nlohmann::json finals = nlohmann::json::object();
  for (const auto &[name, d] : recorder.pointDisplacements(uAll)) finals[name] = {d.x(), d.y(), d.z()};
  doc["final_displacement"] = finals;
  doc["final_time"] = t;
  doc["converged"] = converged == 1;
  doc["running"] = false;
  if (!failure.empty()) doc["failure"] = failure;
  writeSummary();
  if (talk) {
    if (converged) std::printf("glossa: done in %.2f s; results in %s\n", since(start), dir.c_str());
    else std::printf("glossa: stopped: %s; results so far in %s\n", failure.c_str(), dir.c_str());
  }
  return doc;
}

} // namespace glossa::solvers
