#include "solvers/Simulation.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <sys/resource.h>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include "assembly/Assembler.hpp"
#include "assembly/ModelEvaluator.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "io/output/ResultWriter.hpp"
#include "io/output/SummaryWriter.hpp"
#include "io/output/TraceWriter.hpp"
#include "model/SceneFactory.hpp"
#include "solvers/LinearSolverFactory.hpp"
#include "solvers/NewtonSolver.hpp"
#include "solvers/TimeStepping.hpp"
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

// Writes the fields of one converged step (rank 0 writes; every rank gathers).
class Recorder {
public:
  Recorder(const assembly::Assembler &assembler, const std::filesystem::path &dir, bool fields)
      : assembler_(assembler), root_(assembler.comm()->getRank() == 0), fields_(fields) {
    if (!root_) return;
    const auto &mesh = assembler.scene().mesh;
    if (fields_) results_ = std::make_unique<io::ResultWriter>(dir, "results", mesh.nodes, mesh.elements);
    traces_ = std::make_unique<io::TraceWriter>(dir / "traces.csv");
  }

  // Displacement of every traced point (on every rank).
  std::vector<std::pair<std::string, Eigen::Vector3d>> pointDisplacements(const std::vector<double> &u) const {
    std::vector<std::pair<std::string, Eigen::Vector3d>> out;
    const auto &mesh = assembler_.scene().mesh;
    for (const auto &name : assembler_.scene().tracedPoints) {
      const auto node = mesh.namedPoints.at(name).node;
      out.emplace_back(name, Eigen::Vector3d(u[3 * node], u[3 * node + 1], u[3 * node + 2]));
    }
    return out;
  }

  void record(double time, const assembly::Vector &u, const std::vector<double> &lambda, bool writeFields) {
    const std::vector<double> uAll = assembler_.gatherDisplacement(u);
    if (root_) traces_->append(time, pointDisplacements(uAll));
    if (!fields_ || !writeFields) return;
    const auto f = assembler_.elementFields(u, lambda);
    std::vector<double> stress;
    for (const auto &s : f.cauchy)
      for (double v : {s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(0, 2)}) stress.push_back(v);
    auto pressure = assembler_.gatherElementField(f.pressure, 1);
    auto theta = assembler_.gatherElementField(f.theta, 1);
    auto minJ = assembler_.gatherElementField(f.minJ, 1);
    auto cauchy = assembler_.gatherElementField(stress, 6);
    if (!root_) return;
    results_->writeStep(time, {{"displacement", 3, uAll}},
                        {{"pressure", 1, pressure}, {"dilatation", 1, theta}, {"J", 1, minJ}, {"cauchy_stress", 6, cauchy}});
  }

private:
  const assembly::Assembler &assembler_;
  bool root_, fields_;
  std::unique_ptr<io::ResultWriter> results_;
  std::unique_ptr<io::TraceWriter> traces_;
};
} // namespace

void declareSolverParameters(Teuchos::ParameterList &schema) {
  schema.set("Time", timeParameters(), "load/time stepping");
  schema.set("Incompressibility", incompressibilityParameters(), "the incompressibility algorithm");
  schema.set("Nonlinear solver", nonlinearSolverParameters(), "Newton's method (NOX)");
  schema.set("Linear solver", linearSolverParameters(), "Krylov solver and preconditioner (Belos, MueLu, Ifpack2, Amesos2)");
  schema.set("Output", outputParameters(), "result files");
}

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

  auto assembler = Teuchos::rcp(new assembly::Assembler(scene, comm));
  LinearSolverContext context{assembler->coordinates(), assembler->rigidBodyModes(), comm->getSize(),
                              assembler->layout().numGlobalDofs(), scene.symmetricTangent};
  const auto &linearSection = D.sublist("Linear solver");
  auto model = Teuchos::rcp(new assembly::ModelEvaluator(assembler, buildLinearSolver(linearSection, context)));
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
  Recorder recorder(*assembler, dir, D.sublist("Output").get<bool>("fields"));
  const int every = D.sublist("Output").get<int>("every");

  std::unique_ptr<io::SummaryWriter> summary;
  nlohmann::json doc;
  doc["deck"] = deck.file();
  doc["converged"] = false;
  doc["running"] = true;
  doc["ranks"] = comm->getSize();
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
  recorder.record(0.0, u, lambda, true);
  writeSummary();

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
    assembler->applyDirichlet(uTrial, tNew);
    model->setTime(tNew);
    model->setLambda(&lambdaTrial);

    // The Newton tolerance scales with the load: the external force and the step's initial residual.
    assembly::Vector f0(assembler->ownedMap());
    std::vector<double> lambdaNow = lambdaTrial;
    assembler->assemble(uTrial, tNew, lambdaNow, nullptr, &f0, nullptr);
    double reference = std::max(assembler->externalForceNorm(tNew), f0.norm2());
    if (!(reference > 0.0)) reference = 1.0;
    const double tolerance = newton.relativeResidualTolerance() * reference;

    if (talk) std::printf("step %d  t = %.6g  dt = %.3g\n", stepNumber + 1, tNew, dt);
    auto onNewton = [&](int k, double normF, int krylov) {
      if (talk) std::printf("    newton %2d  |f| = %.3e  krylov %d\n", k, normF, krylov);
    };
    auto onUzawa = [&](int k, const NewtonResult &n, const DilatationError &e) {
      if (talk)
        std::printf("  uzawa %d: newton %d  krylov %d  dilatation error max %.2e  mean %.2e  max|theta-1| %.2e\n", k,
                    n.iterations, n.linearIterations, e.max, e.mean, e.maxVolumeChange);
    };
    UzawaResult r = uzawa.solve(uTrial, lambdaTrial, tolerance, onNewton, onUzawa);
    model->setLambda(nullptr);

    if (!r.converged) {
      const NewtonResult &last = r.newton.back();
      const std::string why = r.elementInverted ? "an element inverted (J <= 0)"
                              : !last.failure.empty() ? last.failure.substr(0, last.failure.find('\n'))
                              : !last.converged ? "Newton did not converge"
                                                : "Uzawa did not reach the dilatation tolerance";
      if (talk) std::printf("  step failed at t = %.6g: %s; cutting back\n", tNew, why.c_str());
      if (!steps.cutBack()) {
        failure = "step to t = " + std::to_string(tNew) + " failed (" + why + ") below the minimum step size";
        converged = 0;
        break;
      }
      continue;
    }
    // Commit.
    u.assign(uTrial);
    lambda = lambdaTrial;
    t = tNew;
    ++stepNumber;
    steps.accept();
    const bool last = t >= steps.endTime() * (1.0 - 1e-12);
    recorder.record(t, u, lambda, last || stepNumber % every == 0);

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
    doc["steps"].push_back(step);
    if (talk)
      std::printf("step %d done  t = %.6g  newton %d  krylov %d  uzawa %d  dilatation error %.2e  [%.2f s]\n", stepNumber,
                  t, r.newtonIterations, r.linearIterations, r.solves, r.dilatation.max, since(start));
    writeSummary();
  }

  const std::vector<double> uAll = assembler->gatherDisplacement(u);
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
