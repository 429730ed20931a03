#include "solvers/parameters/LinearSolverParameters.hpp"

#include "io/deck/ParameterSpec.hpp"

namespace glossa::solvers {

Teuchos::ParameterList linearSolverParameters() {
  Teuchos::ParameterList p;
  io::declareString(p, "type", "auto",
                    "auto: direct up to 'direct up to' unknowns, iterative above; iterative: Belos Krylov "
                    "solver with the 'preconditioner'; direct: the 'direct solver'",
                    {"auto", "iterative", "direct"});
  io::declareString(p, "direct solver", "MUMPS",
                    "MUMPS: multifrontal LU (LDL^T for a symmetric tangent), analysed once per run and "
                    "refactored as 'direct reuse iterations' says, inside the Krylov method (MPI-parallel); KLU2: "
                    "Amesos2 KLU2 (slow on 3D meshes, kept for comparison; one rank)",
                    {"MUMPS", "KLU2"});
  io::declareInt(p, "direct up to", 8000,
                 "type = auto: the largest number of unknowns solved directly, on any number of ranks R "
                 "(gathered onto rank 0 up to this / R; the measured crossover with MueLu on the step-44 block "
                 "lies between 6,591 and 14,739 on one rank, above 6,591 on two; doc/incompressibility.md)",
                 io::Range::atLeast(0));
  io::declareString(p, "direct ordering", "auto",
                    "MUMPS's fill-reducing ordering (ICNTL(7)): auto, PORD from 1,000 unknowns and MUMPS's own choice "
                    "below (AMF, QAMD); PORD, AMD, AMF, QAMD always (PORD fails on a single element; doc/performance.md)",
                    {"auto", "PORD", "AMD", "AMF", "QAMD"});
  io::declareString(p, "direct distribution", "auto",
                    "MUMPS on several ranks: gathered (the entries gathered onto rank 0 and factored there "
                    "alone: the same answer bit for bit run after run, so a restart ends as the uninterrupted "
                    "run), distributed (every rank factors its share; the last bits vary from run to run), "
                    "auto: gathered when type = auto chose the direct solve for at most 'direct up to' / R unknowns on R "
                    "ranks, distributed otherwise",
                    {"auto", "gathered", "distributed"});
  io::declareInt(p, "direct reuse iterations", 10,
                 "MUMPS: 0 refactors the tangent at every Newton iteration; k > 0 factors at the first iteration of each "
                 "Newton solve (one tightening the Uzawa loop's inexact one continues it) and keeps the factors as the Krylov "
                 "method's preconditioner while a solve takes at most k iterations (doc/incompressibility.md)",
                 io::Range::atLeast(0));
  io::declareString(p, "direct reuse scope", "Newton solve",
                    "MUMPS, with 'direct reuse iterations' > 0: how long kept factors live: Newton solve "
                    "(the default: refactored at the first iteration of each Newton solve; step when the airflow "
                    "is coupled inside the Uzawa loop), step (kept across "
                    "the Uzawa iterations of a step, refactored when a step, a retry or a controller's "
                    "candidate starts; restarts stay deterministic; faster, but a step's later Newton solves "
                    "lose their quadratic convergence; measured: doc/incompressibility.md) or run (kept across "
                    "steps while they serve; a restarted run's iterates differ within the solver tolerances)",
                    {"Newton solve", "step", "run"});
  io::declareString(p, "sensitivity solve", "auto",
                    "a controller's sensitivities (one tangent, a right-hand side per muscle group): direct "
                    "(MUMPS factors each such tangent afresh, once for all its right-hand sides), as Newton "
                    "(Newton's solver: its Krylov method, or its factors); auto: direct where Newton's solve is "
                    "MUMPS, and beside an iterative one up to 30,000 unknowns (measured: doc/performance.md)",
                    {"auto", "as Newton", "direct"});
  io::declareString(p, "Krylov method", "auto",
                    "auto: CG while the tangent is symmetric, GMRES otherwise", {"auto", "cg", "gmres"});
  io::declareString(p, "preconditioner", "MueLu",
                    "MueLu: smoothed-aggregation AMG with rigid-body modes; FROSch: two-level "
                    "overlapping Schwarz (ShyLU_DDFROSch, one subdomain per rank, KLU2 subdomain and "
                    "coarse solves); Ifpack2: the 'Ifpack2 type' alone; none",
                    {"MueLu", "FROSch", "Ifpack2", "none"});
  io::declareString(p, "FROSch coarse space", "GDSW",
                    "GDSW or RGDSW (reduced dimension) energy-minimising coarse space, translations "
                    "and rotations (from the nodal coordinates)", {"GDSW", "RGDSW"});
  io::declareInt(p, "FROSch overlap", 1, "layers of matrix-graph overlap added to each rank's subdomain",
                 io::Range::closed(0, 10));
  io::declareDouble(p, "tolerance", 1e-6, "",
                    "relative residual reduction of each linear solve (Newton still converges to "
                    "its own tolerance; 1e-6 is also step-44's choice)",
                    io::Range::open(0.0, 1.0));
  io::declareInt(p, "maximum iterations", 2000, "Krylov iteration limit per solve", io::Range::atLeast(1));
  io::declareInt(p, "GMRES restart", 200, "Krylov vectors kept by GMRES", io::Range::atLeast(10));
  io::declareString(p, "MueLu smoother", "Chebyshev",
                    "Chebyshev (polynomial, every level); symmetric Gauss-Seidel (point, every level); "
                    "node-block Gauss-Seidel (symmetric, on each node's 3x3 block, 6x6 on coarse levels); "
                    "vertex-patch (Ifpack2 BLOCK RELAXATION: symmetric Gauss-Seidel on overlapping "
                    "patches, each node with its matrix-graph neighbours, i.e. the 27 nodes of the "
                    "elements around a vertex; on 'vertex-patch levels', Chebyshev elsewhere)",
                    {"Chebyshev", "symmetric Gauss-Seidel", "node-block Gauss-Seidel", "vertex-patch"});
  io::declareInt(p, "smoother degree", 6,
                 "Chebyshev degree, or Gauss-Seidel sweeps (point and node-block: 2 is the measured choice, "
                 "set it when choosing them); the Chebyshev levels of the vertex-patch smoother use it as "
                 "their degree (6 with eigenvalue ratio 100: the default, doc/incompressibility.md)",
                 io::Range::closed(1, 20));
  io::declareString(p, "vertex-patch levels", "finest",
                    "where the vertex-patch smoother runs: finest (Chebyshev on the coarse levels) or all",
                    {"finest", "all"});
  io::declareInt(p, "patch sweeps", 1, "symmetric Gauss-Seidel sweeps of the vertex-patch smoother",
                 io::Range::closed(1, 10));
  io::declareString(p, "Chebyshev eigenvalue method", "Lanczos",
                    "how the Chebyshev smoother estimates the largest eigenvalue of D^-1 A: Lanczos (CG "
                    "steps; 15 give it to 6 digits on the active-muscle block) or power iterations (they "
                    "converge from below and slowly: 20 left the degree-6 smoother indefinite there and "
                    "broke CG); a nonsymmetric tangent (follower loads, external muscles) always uses "
                    "power iterations, since Lanczos broke down on it (doc/incompressibility.md)",
                    {"Lanczos", "power"});
  io::declareInt(p, "Chebyshev eigenvalue iterations", 0,
                 "steps of the eigenvalue method; 0: its default, 15 Lanczos steps or 50 power iterations "
                 "(an underestimate makes the degree-6 smoother indefinite and breaks CG: 6 Lanczos steps "
                 "and 20 power iterations did on the active-muscle block)", io::Range::closed(0, 200));
  io::declareDouble(p, "Chebyshev eigenvalue ratio", 100.0, "",
                    "lambda_max / lambda_min of the interval the Chebyshev smoother damps",
                    io::Range::atLeast(2.0));
  io::declareString(p, "MueLu reuse", "RAP",
                    "what MueLu keeps between Newton iterations: none (rebuild), RP (aggregates and "
                    "transfer operators; coarse matrices and smoothers recomputed), RAP (the default: "
                    "also the coarse matrices and their smoothers and coarse solve, stale; only the "
                    "finest smoother is rebuilt; measured in doc/incompressibility.md), full (the "
                    "whole hierarchy, stale); the vertex-patch "
                    "smoother always uses none (Ifpack2 13.2's overlapping block relaxation returns "
                    "NaN when reused; it runs on one rank only)",
                    {"none", "RP", "RAP", "full"});
  io::declareString(p, "MueLu reuse scope", "step",
                    "how long a reused hierarchy lives: Newton solve (rebuilt at the start of every "
                    "Newton solve, i.e. every Uzawa iteration), step (the default: kept across the "
                    "Uzawa iterations of a load step, rebuilt when a step or a retry starts, so runs "
                    "and restarts stay deterministic) or run (kept across load steps; a restarted "
                    "run's iterates differ within the solver tolerances); only with MueLu reuse = RP, "
                    "RAP or full, and only for the iterative solve with MueLu",
                    {"Newton solve", "step", "run"});
  io::declareInt(p, "coarse size", 2000, "MueLu stops coarsening below this many rows", io::Range::atLeast(10));
  io::declareString(p, "Ifpack2 type", "symmetric Gauss-Seidel",
                    "single-level preconditioner when preconditioner = Ifpack2",
                    {"symmetric Gauss-Seidel", "Chebyshev", "ILUT"});
  io::declareBool(p, "verbose", false, "print the Krylov solver's convergence history");
  return p;
}

namespace {
ReuseScope reuseScopeOf(const std::string &word) {
  return word == "run" ? ReuseScope::run : word == "step" ? ReuseScope::step : ReuseScope::newtonSolve;
}
} // namespace

LinearSolverParameters parseLinearSolverParameters(const Teuchos::ParameterList &s) {
  LinearSolverParameters p;
  const std::string type = s.get<std::string>("type");
  p.type = type == "direct" ? LinearSolverType::direct : type == "iterative" ? LinearSolverType::iterative : LinearSolverType::automatic;
  p.directSolverName = s.get<std::string>("direct solver");
  p.directSolver = p.directSolverName == "KLU2" ? DirectSolver::klu2 : DirectSolver::mumps;
  p.directUpTo = s.get<int>("direct up to");
  p.directOrdering = s.get<std::string>("direct ordering");
  const std::string distribution = s.get<std::string>("direct distribution");
  p.directDistribution = distribution == "gathered"      ? DirectDistribution::gathered
                         : distribution == "distributed" ? DirectDistribution::distributed
                                                         : DirectDistribution::automatic;
  p.directReuseIterations = s.get<int>("direct reuse iterations");
  p.directReuseScope = reuseScopeOf(s.get<std::string>("direct reuse scope"));
  const std::string sensitivity = s.get<std::string>("sensitivity solve");
  p.sensitivitySolve = sensitivity == "direct"      ? SensitivitySolve::direct
                       : sensitivity == "as Newton" ? SensitivitySolve::asNewton
                                                    : SensitivitySolve::automatic;
  const std::string krylov = s.get<std::string>("Krylov method");
  p.krylovMethod = krylov == "cg" ? KrylovMethod::cg : krylov == "gmres" ? KrylovMethod::gmres : KrylovMethod::automatic;
  p.preconditionerName = s.get<std::string>("preconditioner");
  const std::string &prec = p.preconditionerName;
  p.preconditioner = prec == "FROSch"    ? Preconditioner::frosch
                     : prec == "Ifpack2" ? Preconditioner::ifpack2
                     : prec == "none"    ? Preconditioner::none
                                         : Preconditioner::mueLu;
  p.froschCoarseSpace = s.get<std::string>("FROSch coarse space") == "GDSW" ? FroschCoarseSpace::gdsw : FroschCoarseSpace::rgdsw;
  p.froschOverlap = s.get<int>("FROSch overlap");
  p.tolerance = s.get<double>("tolerance");
  p.maximumIterations = s.get<int>("maximum iterations");
  p.gmresRestart = s.get<int>("GMRES restart");
  const std::string smoother = s.get<std::string>("MueLu smoother");
  p.mueLuSmoother = smoother == "symmetric Gauss-Seidel"    ? MueLuSmoother::symmetricGaussSeidel
                    : smoother == "node-block Gauss-Seidel" ? MueLuSmoother::nodeBlockGaussSeidel
                    : smoother == "vertex-patch"            ? MueLuSmoother::vertexPatch
                                                            : MueLuSmoother::chebyshev;
  p.smootherDegree = s.get<int>("smoother degree");
  p.vertexPatchLevels = s.get<std::string>("vertex-patch levels") == "all" ? VertexPatchLevels::all : VertexPatchLevels::finest;
  p.patchSweeps = s.get<int>("patch sweeps");
  p.chebyshevEigenvalueMethod =
      s.get<std::string>("Chebyshev eigenvalue method") == "power" ? EigenvalueMethod::power : EigenvalueMethod::lanczos;
  p.chebyshevEigenvalueIterations = s.get<int>("Chebyshev eigenvalue iterations");
  p.chebyshevEigenvalueRatio = s.get<double>("Chebyshev eigenvalue ratio");
  p.mueLuReuse = s.get<std::string>("MueLu reuse");
  p.reuseScope = reuseScopeOf(s.get<std::string>("MueLu reuse scope"));
  p.coarseSize = s.get<int>("coarse size");
  const std::string ifpack2 = s.get<std::string>("Ifpack2 type");
  p.ifpack2Type = ifpack2 == "ILUT" ? Ifpack2Type::ilut : ifpack2 == "Chebyshev" ? Ifpack2Type::chebyshev : Ifpack2Type::symmetricGaussSeidel;
  p.verbose = s.get<bool>("verbose");
  return p;
}

} // namespace glossa::solvers
