#include "solvers/LinearSolverFactory.hpp"

#include <algorithm>

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Stratimikos_FROSch_def.hpp>
#include <Stratimikos_MueLuHelpers.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>
#include <Thyra_Ifpack2PreconditionerFactory.hpp>

#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "solvers/MumpsPreconditioner.hpp"

namespace glossa::solvers {

using Teuchos::ParameterList;

ParameterList linearSolverParameters() {
  ParameterList p;
  io::declareString(p, "type", "auto",
                    "auto: direct on one rank up to 'direct up to' unknowns, iterative otherwise; iterative: Belos Krylov "
                    "solver with the 'preconditioner'; direct: the 'direct solver'",
                    {"auto", "iterative", "direct"});
  io::declareString(p, "direct solver", "MUMPS",
                    "MUMPS: multifrontal LU (LDL^T for a symmetric tangent), analysed once per run and "
                    "refactored every Newton iteration, inside one Krylov iteration (MPI-parallel); KLU2: "
                    "Amesos2 KLU2 (slow on 3D meshes, kept for comparison; one rank)",
                    {"MUMPS", "KLU2"});
  io::declareInt(p, "direct up to", 8000,
                 "type = auto: the largest number of unknowns solved directly (the measured crossover with "
                 "MueLu on the step-44 block lies between 6,591 and 14,739; doc/incompressibility.md)",
                 io::Range::atLeast(0));
  io::declareInt(p, "direct reuse iterations", 10,
                 "MUMPS: 0 refactors the tangent at every Newton iteration; k > 0 factors at the first "
                 "iteration of each Newton solve and keeps the factors as the Krylov method's preconditioner "
                 "while a solve takes at most k iterations (measured: doc/incompressibility.md)",
                 io::Range::atLeast(0));
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
  io::declareInt(p, "Chebyshev eigenvalue iterations", 50,
                 "power iterations estimating the largest eigenvalue: an underestimate makes the degree-6 "
                 "smoother indefinite and breaks CG (20 did on the active-muscle block, 10 for nu >= 0.49 "
                 "on the step-44 block; doc/incompressibility.md)", io::Range::closed(5, 200));
  io::declareDouble(p, "Chebyshev eigenvalue ratio", 100.0, "",
                    "lambda_max / lambda_min of the interval the Chebyshev smoother damps",
                    io::Range::atLeast(2.0));
  io::declareString(p, "MueLu reuse", "RP",
                    "what MueLu keeps between Newton iterations: none (rebuild), RP (aggregates and "
                    "transfer operators; coarse matrices and smoothers recomputed), RAP (also the "
                    "coarse matrices and their smoothers and coarse solve, stale; only the finest "
                    "smoother is rebuilt), full (the whole hierarchy, stale); the vertex-patch "
                    "smoother always uses none (Ifpack2 13.2's overlapping block relaxation returns "
                    "NaN when reused; it runs on one rank only)",
                    {"none", "RP", "RAP", "full"});
  io::declareString(p, "MueLu reuse scope", "Newton solve",
                    "how long a reused hierarchy lives: Newton solve (rebuilt at the start of every "
                    "Newton solve, i.e. every Uzawa iteration and load step) or run (kept across "
                    "Uzawa iterations and load steps; only with MueLu reuse = RP, RAP or full)",
                    {"Newton solve", "run"});
  io::declareInt(p, "coarse size", 2000, "MueLu stops coarsening below this many rows", io::Range::atLeast(10));
  io::declareString(p, "Ifpack2 type", "symmetric Gauss-Seidel",
                    "single-level preconditioner when preconditioner = Ifpack2",
                    {"symmetric Gauss-Seidel", "Chebyshev", "ILUT"});
  io::declareBool(p, "verbose", false, "print the Krylov solver's convergence history");
  return p;
}

namespace {
ParameterList mueluParameters(const ParameterList &s, const LinearSolverContext &c) {
  ParameterList m;
  m.set("verbosity", s.get<bool>("verbose") ? "low" : "none");
  m.set("number of equations", 3);
  m.set("multigrid algorithm", "sa");
  int coarseSize = s.get<int>("coarse size");
  if (c.ranks > 1 && c.globalRows > 0) {
    // A one-level hierarchy would hand the whole distributed matrix to KLU2, whose multi-rank
    // path is wrong here (doc/developing.md, measured Trilinos facts): make sure there is a coarse level to gather.
    coarseSize = static_cast<int>(std::min<long long>(coarseSize, std::max<long long>(c.globalRows / 8, 3)));
  }
  m.set("coarse: max size", coarseSize);
  // Ifpack2 13.2's BLOCK RELAXATION with overlapping parts returns NaN after MueLu reuses it
  // (measured: every reuse type but none, finest or all levels): the vertex patch always rebuilds.
  const bool overlappingBlocks = s.get<std::string>("MueLu smoother") == "vertex-patch";
  if (overlappingBlocks && c.ranks > 1)
    throw io::DeckError("Linear solver/MueLu smoother = vertex-patch runs on one rank only: on 2 ranks its "
                        "patches are cut at the partition boundary and CG broke down (doc/incompressibility.md)");
  m.set("reuse: type", overlappingBlocks ? std::string("none") : s.get<std::string>("MueLu reuse"));
  const int degree = s.get<int>("smoother degree");
  const std::string smoother = s.get<std::string>("MueLu smoother");
  auto chebyshev = [&](ParameterList &level) {
    level.set("smoother: type", "CHEBYSHEV");
    ParameterList &sp = level.sublist("smoother: params");
    sp.set("chebyshev: degree", degree);
    sp.set("chebyshev: eigenvalue max iterations", s.get<int>("Chebyshev eigenvalue iterations"));
    sp.set("chebyshev: ratio eigenvalue", s.get<double>("Chebyshev eigenvalue ratio"));
  };
  // Ifpack2 BLOCK RELAXATION with the "linear" partitioner: MueLu sets one part per node (rows /
  // the level's block size: 3 dofs on the finest level, 6 on coarse ones, the rows being node-
  // ordered); overlap 1 grows each part by its matrix-graph neighbours (the vertex patch). Dense
  // containers: the default tridiagonal one would drop most of each block.
  auto blockRelaxation = [&](ParameterList &level, int overlap, int sweeps) {
    level.set("smoother: type", "BLOCK RELAXATION");
    ParameterList &sp = level.sublist("smoother: params");
    sp.set("relaxation: type", "Symmetric Gauss-Seidel");
    sp.set("relaxation: sweeps", sweeps);
    sp.set("relaxation: container", "Dense");
    sp.set("partitioner: type", "linear");
    sp.set("partitioner: overlap", overlap);
  };
  if (smoother == "Chebyshev") {
    chebyshev(m);
  } else if (smoother == "node-block Gauss-Seidel") {
    blockRelaxation(m, 0, degree);
  } else if (smoother == "vertex-patch") {
    if (s.get<std::string>("vertex-patch levels") == "all") {
      blockRelaxation(m, 1, s.get<int>("patch sweeps"));
    } else {
      chebyshev(m);
      blockRelaxation(m.sublist("level 0"), 1, s.get<int>("patch sweeps"));
    }
  } else {
    m.set("smoother: type", "RELAXATION");
    ParameterList &sp = m.sublist("smoother: params");
    sp.set("relaxation: type", "Symmetric Gauss-Seidel");
    sp.set("relaxation: sweeps", degree);
  }
  if (c.ranks > 1) {
    // KLU2's multi-process path is wrong here (doc/developing.md, measured Trilinos facts): gather the coarse levels onto
    // one rank by repartitioning instead.
    m.set("repartition: enable", true);
    m.set("repartition: partitioner", "zoltan2");
    m.set("repartition: start level", 1);
    m.set("repartition: min rows per proc", 2000);
  }
  if (!c.coordinates.is_null()) m.set("Coordinates", c.coordinates);
  if (!c.rigidBodyModes.is_null()) m.set("Nullspace", c.rigidBodyModes);
  return m;
}

ParameterList froschParameters(const ParameterList &s, const LinearSolverContext &c) {
  // Parameter names from FROSch's TwoLevelPreconditioner and GDSW/RGDSW coarse operators (13.2).
  ParameterList f;
  f.set("FROSch Preconditioner Type", "TwoLevelPreconditioner");
  f.set("Dimension", 3);
  f.set("DofsPerNode", 3);
  f.set("DofOrdering", "NodeWise"); // dof = 3 node + component (DofLayout)
  f.set("Overlap", s.get<int>("FROSch overlap"));
  f.set("OverlappingOperator Type", "AlgebraicOverlappingOperator");
  ParameterList &overlapping = f.sublist("AlgebraicOverlappingOperator");
  overlapping.sublist("Solver").set("SolverType", "Amesos2").set("Solver", "Klu");
  overlapping.set("Verbosity", "None");
  // Additive (Full) rather than the default restricted Schwarz: RAS is not symmetric and CG broke
  // down on it on 2 ranks (non-positive p^H A p).
  overlapping.set("Combine Values in Overlap", "Full");
  const std::string coarse = s.get<std::string>("FROSch coarse space") == "GDSW" ? "GDSWCoarseOperator"
                                                                                  : "RGDSWCoarseOperator";
  f.set("CoarseOperator Type", coarse);
  ParameterList &co = f.sublist(coarse);
  co.sublist("Blocks").sublist("1").set("Use For Coarse Space", true).set("Rotations", true).set("Verbosity", "None");
  co.sublist("ExtensionSolver").set("SolverType", "Amesos2").set("Solver", "Klu");
  // The coarse problem on one rank: KLU2's multi-process path is wrong here (doc/developing.md, measured Trilinos facts).
  co.sublist("Distribution").set("Type", "linear").set("NumProcs", 1);
  co.sublist("CoarseSolver").set("SolverType", "Amesos2").set("Solver", "Klu");
  co.set("Verbosity", "None");
  f.set("Verbosity", "None");
  if (!c.coordinates.is_null()) f.set("Coordinates List", c.coordinates);
  return f;
}

ParameterList ifpack2Parameters(const ParameterList &s) {
  ParameterList p;
  const std::string type = s.get<std::string>("Ifpack2 type");
  if (type == "ILUT") {
    p.set("Prec Type", "ILUT");
  } else if (type == "Chebyshev") {
    p.set("Prec Type", "CHEBYSHEV");
    p.sublist("Ifpack2 Settings").set("chebyshev: degree", s.get<int>("smoother degree"));
    p.sublist("Ifpack2 Settings").set("chebyshev: eigenvalue max iterations", s.get<int>("Chebyshev eigenvalue iterations"));
  } else {
    p.set("Prec Type", "RELAXATION");
    p.sublist("Ifpack2 Settings").set("relaxation: type", "Symmetric Gauss-Seidel");
    p.sublist("Ifpack2 Settings").set("relaxation: sweeps", s.get<int>("smoother degree"));
  }
  return p;
}
} // namespace

bool usesDirectSolve(const ParameterList &s, const LinearSolverContext &c) {
  const std::string type = s.get<std::string>("type");
  // auto is direct on one rank only: MUMPS schedules its parallel factorisation dynamically, so on
  // several ranks the last bits of an answer may differ from run to run (restart would not end
  // bit for bit as an uninterrupted run), and small problems need no second rank.
  if (type == "auto") return c.ranks == 1 && c.globalRows > 0 && c.globalRows <= s.get<int>("direct up to");
  return type == "direct";
}

Teuchos::RCP<ParameterList> stratimikosParameters(const ParameterList &s, const LinearSolverContext &c) {
  auto p = Teuchos::rcp(new ParameterList("Linear solver"));
  const bool direct = usesDirectSolve(s, c);
  if (direct && s.get<std::string>("direct solver") == "KLU2") {
    p->set("Linear Solver Type", "Amesos2");
    p->sublist("Linear Solver Types").sublist("Amesos2").set("Solver Type", "KLU2");
    p->set("Preconditioner Type", "None");
    return p;
  }
  std::string method = s.get<std::string>("Krylov method");
  if (method == "auto") method = c.symmetric ? "cg" : "gmres";
  const std::string belosName = method == "cg" ? "Block CG" : "Block GMRES";
  p->set("Linear Solver Type", "Belos");
  ParameterList &belos = p->sublist("Linear Solver Types").sublist("Belos");
  belos.set("Solver Type", belosName);
  ParameterList &solver = belos.sublist("Solver Types").sublist(belosName);
  solver.set("Convergence Tolerance", s.get<double>("tolerance"));
  solver.set("Maximum Iterations", s.get<int>("maximum iterations"));
  if (method == "gmres") solver.set("Num Blocks", s.get<int>("GMRES restart"));
  if (s.get<bool>("verbose")) {
    solver.set("Verbosity", 33); // Errors + StatusTestDetails + FinalSummary
    solver.set("Output Frequency", 10);
    belos.sublist("VerboseObject").set("Verbosity Level", "medium");
  }
  const std::string prec = direct ? std::string("MUMPS") : s.get<std::string>("preconditioner");
  if (prec == "MUMPS") {
    // The exact inverse inside the Krylov method: one iteration, with its residual check.
    p->set("Preconditioner Type", "MUMPS");
    auto &mumps = p->sublist("Preconditioner Types").sublist("MUMPS");
    mumps.set("symmetric", c.symmetric);
    mumps.set("reuse iterations", s.get<int>("direct reuse iterations"));
  } else if (prec == "MueLu") {
    p->set("Preconditioner Type", "MueLu");
    p->sublist("Preconditioner Types").set("MueLu", mueluParameters(s, c));
  } else if (prec == "FROSch") {
    p->set("Preconditioner Type", "FROSch");
    p->sublist("Preconditioner Types").set("FROSch", froschParameters(s, c));
  } else if (prec == "Ifpack2") {
    p->set("Preconditioner Type", "Ifpack2");
    p->sublist("Preconditioner Types").set("Ifpack2", ifpack2Parameters(s));
  } else {
    p->set("Preconditioner Type", "None");
  }
  return p;
}

namespace {
void registerPreconditioners(Stratimikos::DefaultLinearSolverBuilder &builder) {
  Stratimikos::enableMueLu<assembly::LO, assembly::GO, assembly::Node>(builder);
  Stratimikos::enableFROSch<assembly::LO, assembly::GO, assembly::Node>(builder);
  using Base = Thyra::PreconditionerFactoryBase<double>;
  using Impl = Thyra::Ifpack2PreconditionerFactory<assembly::CrsMatrix>;
  builder.setPreconditioningStrategyFactory(Teuchos::abstractFactoryStd<Base, Impl>(), "Ifpack2");
  builder.setPreconditioningStrategyFactory(Teuchos::abstractFactoryStd<Base, MumpsPreconditionerFactory>(), "MUMPS");
}
} // namespace

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>>
buildLinearSolver(const ParameterList &section, const LinearSolverContext &context) {
  Stratimikos::DefaultLinearSolverBuilder builder;
  registerPreconditioners(builder);
  builder.setParameterList(stratimikosParameters(section, context));
  return builder.createLinearSolveStrategy("");
}

Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>>
buildDisplacementPreconditioner(const ParameterList &section, const LinearSolverContext &context) {
  Stratimikos::DefaultLinearSolverBuilder builder;
  registerPreconditioners(builder);
  LinearSolverContext displacementBlock = context;
  displacementBlock.symmetric = true; // K at fixed pressure is the symmetric part of a symmetric tangent
  ParameterList block = section;
  block.set("direct solver", "MUMPS"); // a preconditioner, which KLU2 through Amesos2 is not
  builder.setParameterList(stratimikosParameters(block, displacementBlock));
  return builder.createPreconditioningStrategy("");
}

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> buildBlockKrylovSolver(const ParameterList &section) {
  ParameterList krylov = section;
  krylov.set("Krylov method", "gmres"); // the block system is indefinite: no CG
  krylov.set("preconditioner", "none");
  Stratimikos::DefaultLinearSolverBuilder builder;
  builder.setParameterList(stratimikosParameters(krylov, {}));
  return builder.createLinearSolveStrategy("");
}

} // namespace glossa::solvers
