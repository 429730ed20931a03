#include "solvers/linear/LinearSolverFactory.hpp"

#include <algorithm>

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>

#include "io/deck/DeckError.hpp"
#include "solvers/linear/CollectivePreconditioner.hpp"
#include "solvers/linear/LinearSolverChoice.hpp"
#include "solvers/linear/MumpsPreconditioner.hpp"
#include "solvers/linear/PreconditionerRegistration.hpp"

namespace glossa::solvers {

using Teuchos::ParameterList;

namespace {
// Ifpack2's words. "cg" is a Lanczos estimate from CG's coefficients: its Ritz value converges to
// lambda_max far faster than the power method, whose underestimate leaves the top of the spectrum
// outside the smoother's interval. Lanczos needs a symmetric matrix: on the nonsymmetric tangents
// of the tongue's control scenes it estimated 0.96 where lambda_max is about 11.7 (no estimate of
// D^-1 A with a unit diagonal can be below 1) and GMRES stalled at its iteration limit, so a
// nonsymmetric tangent always uses the power method (doc/incompressibility.md).
bool powerMethod(const LinearSolverParameters &s, const LinearSolverContext &c) {
  return s.chebyshevEigenvalueMethod == EigenvalueMethod::power || !c.symmetric;
}
std::string eigenAnalysisType(const LinearSolverParameters &s, const LinearSolverContext &c) {
  return powerMethod(s, c) ? "power method" : "cg";
}
// The deck's count, or the method's default: 15 Lanczos steps, 50 power iterations (20 left the
// degree-6 smoother indefinite on the active-muscle block).
int eigenvalueIterations(const LinearSolverParameters &s, const LinearSolverContext &c) {
  if (s.chebyshevEigenvalueIterations > 0) return s.chebyshevEigenvalueIterations;
  return powerMethod(s, c) ? 50 : 15;
}

ParameterList mueluParameters(const LinearSolverParameters &s, const LinearSolverContext &c) {
  ParameterList m;
  m.set("verbosity", s.verbose ? "low" : "none");
  m.set("number of equations", 3);
  m.set("multigrid algorithm", "sa");
  int coarseSize = s.coarseSize;
  if (c.ranks > 1 && c.globalRows > 0) {
    // A one-level hierarchy would hand the whole distributed matrix to KLU2, whose multi-rank
    // path is wrong here (doc/developing.md, measured Trilinos facts): make sure there is a coarse level to gather.
    coarseSize = static_cast<int>(std::min<long long>(coarseSize, std::max<long long>(c.globalRows / 8, 3)));
  }
  m.set("coarse: max size", coarseSize);
  // Ifpack2 13.2's BLOCK RELAXATION with overlapping parts returns NaN after MueLu reuses it
  // (measured: every reuse type but none, finest or all levels): the vertex patch always rebuilds.
  const bool overlappingBlocks = s.mueLuSmoother == MueLuSmoother::vertexPatch;
  if (overlappingBlocks && c.ranks > 1)
    throw io::DeckError("Linear solver/MueLu smoother = vertex-patch runs on one rank only: on 2 ranks its "
                        "patches are cut at the partition boundary and CG broke down (doc/incompressibility.md)");
  m.set("reuse: type", overlappingBlocks ? std::string("none") : s.mueLuReuse);
  const int degree = s.smootherDegree;
  auto chebyshev = [&](ParameterList &level) {
    level.set("smoother: type", "CHEBYSHEV");
    ParameterList &sp = level.sublist("smoother: params");
    sp.set("chebyshev: degree", degree);
    sp.set("chebyshev: eigenvalue max iterations", eigenvalueIterations(s, c));
    sp.set("eigen-analysis: type", eigenAnalysisType(s, c));
    sp.set("chebyshev: ratio eigenvalue", s.chebyshevEigenvalueRatio);
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
  // On several ranks the coarse levels are gathered onto one rank (below), where a smoother's
  // set-up that fails fails on that rank alone, inside MueLu's set-up while the other ranks go on
  // into its collective calls: nothing after it can bring the ranks back together. Lanczos broke
  // down there (the isometric block at T0s = 1 on 2 ranks: a NaN eigenvalue estimate on level 1,
  // the job dead in MPI_ERR_TRUNCATE); the power method does not break down, so the coarse levels
  // use it (levels 1 to 9: MueLu's default "max levels" is 10).
  auto coarseLevelsByPower = [&] {
    if (c.ranks == 1 || powerMethod(s, c)) return;
    for (int level = 1; level < 10; ++level) {
      ParameterList &l = m.sublist("level " + std::to_string(level));
      chebyshev(l);
      l.sublist("smoother: params").set("eigen-analysis: type", "power method");
      l.sublist("smoother: params").set("chebyshev: eigenvalue max iterations",
                                        s.chebyshevEigenvalueIterations > 0 ? s.chebyshevEigenvalueIterations : 50);
    }
  };
  if (s.mueLuSmoother == MueLuSmoother::chebyshev) {
    chebyshev(m);
    coarseLevelsByPower();
  } else if (s.mueLuSmoother == MueLuSmoother::nodeBlockGaussSeidel) {
    blockRelaxation(m, 0, degree);
  } else if (s.mueLuSmoother == MueLuSmoother::vertexPatch) {
    if (s.vertexPatchLevels == VertexPatchLevels::all) {
      blockRelaxation(m, 1, s.patchSweeps);
    } else {
      chebyshev(m);
      blockRelaxation(m.sublist("level 0"), 1, s.patchSweeps);
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

ParameterList froschParameters(const LinearSolverParameters &s, const LinearSolverContext &c) {
  // Parameter names from FROSch's TwoLevelPreconditioner and GDSW/RGDSW coarse operators (13.2).
  ParameterList f;
  f.set("FROSch Preconditioner Type", "TwoLevelPreconditioner");
  f.set("Dimension", 3);
  f.set("DofsPerNode", 3);
  f.set("DofOrdering", "NodeWise"); // dof = 3 node + component (DofLayout)
  f.set("Overlap", s.froschOverlap);
  f.set("OverlappingOperator Type", "AlgebraicOverlappingOperator");
  ParameterList &overlapping = f.sublist("AlgebraicOverlappingOperator");
  overlapping.sublist("Solver").set("SolverType", "Amesos2").set("Solver", "Klu");
  overlapping.set("Verbosity", "None");
  // Additive (Full) rather than the default restricted Schwarz: RAS is not symmetric and CG broke
  // down on it on 2 ranks (non-positive p^H A p).
  overlapping.set("Combine Values in Overlap", "Full");
  const std::string coarse =
      s.froschCoarseSpace == FroschCoarseSpace::gdsw ? "GDSWCoarseOperator" : "RGDSWCoarseOperator";
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

ParameterList ifpack2Parameters(const LinearSolverParameters &s, const LinearSolverContext &c) {
  ParameterList p;
  if (s.ifpack2Type == Ifpack2Type::ilut) {
    p.set("Prec Type", "ILUT");
  } else if (s.ifpack2Type == Ifpack2Type::chebyshev) {
    p.set("Prec Type", "CHEBYSHEV");
    p.sublist("Ifpack2 Settings").set("chebyshev: degree", s.smootherDegree);
    p.sublist("Ifpack2 Settings").set("chebyshev: eigenvalue max iterations", eigenvalueIterations(s, c));
    p.sublist("Ifpack2 Settings").set("eigen-analysis: type", eigenAnalysisType(s, c));
  } else {
    p.set("Prec Type", "RELAXATION");
    p.sublist("Ifpack2 Settings").set("relaxation: type", "Symmetric Gauss-Seidel");
    p.sublist("Ifpack2 Settings").set("relaxation: sweeps", s.smootherDegree);
  }
  return p;
}
} // namespace

bool usesDirectSolve(const LinearSolverParameters &s, const LinearSolverContext &c) {
  if (c.direct) return *c.direct; // the plan's
  return chooseLinearSolve(s, {c.globalRows, c.ranks}).direct;
}

LinearSolverPlan planLinearSolver(const LinearSolverParameters &s, const LinearSolverContext &c, bool mixedBlockSolve) {
  LinearSolverPlan plan;
  plan.direct = usesDirectSolve(s, c);
  plan.keptScope = plan.direct || s.preconditioner != Preconditioner::mueLu || mixedBlockSolve ? ReuseScope::newtonSolve
                                                                                               : s.reuseScope;
  // With the mixed method: the displacement block's preconditioner.
  plan.description = plan.direct ? "direct (" + s.directSolverName + ")" : "iterative (" + s.preconditionerName + ")";
  return plan;
}

ReuseScope keptReuseScope(const LinearSolverParameters &s, const LinearSolverContext &c, bool mixedBlockSolve) {
  return planLinearSolver(s, c, mixedBlockSolve).keptScope;
}

Teuchos::RCP<ParameterList> stratimikosParameters(const LinearSolverParameters &s, const LinearSolverContext &c) {
  auto p = Teuchos::rcp(new ParameterList("Linear solver"));
  const bool direct = usesDirectSolve(s, c);
  if (direct && s.directSolver == DirectSolver::klu2) {
    p->set("Linear Solver Type", "Amesos2");
    p->sublist("Linear Solver Types").sublist("Amesos2").set("Solver Type", "KLU2");
    p->set("Preconditioner Type", "None");
    return p;
  }
  const bool cg = s.krylovMethod == KrylovMethod::cg || (s.krylovMethod == KrylovMethod::automatic && c.symmetric);
  const std::string belosName = cg ? "Block CG" : "Block GMRES";
  p->set("Linear Solver Type", "Belos");
  ParameterList &belos = p->sublist("Linear Solver Types").sublist("Belos");
  belos.set("Solver Type", belosName);
  ParameterList &solver = belos.sublist("Solver Types").sublist(belosName);
  solver.set("Convergence Tolerance", s.tolerance);
  solver.set("Maximum Iterations", s.maximumIterations);
  if (!cg) solver.set("Num Blocks", s.gmresRestart);
  if (s.verbose) {
    solver.set("Verbosity", 33); // Errors + StatusTestDetails + FinalSummary
    solver.set("Output Frequency", 10);
    belos.sublist("VerboseObject").set("Verbosity Level", "medium");
  }
  if (direct) {
    // The exact inverse inside the Krylov method: one iteration, with its residual check.
    p->set("Preconditioner Type", "MUMPS");
    auto &mumps = p->sublist("Preconditioner Types").sublist("MUMPS");
    mumps.set("symmetric", c.symmetric);
    mumps.set("ordering", s.directOrdering);
    mumps.set("reuse iterations", s.directReuseIterations);
    mumps.set("reuse scope", std::string(s.directReuseScope == ReuseScope::run    ? "run"
                                         : s.directReuseScope == ReuseScope::step ? "step"
                                                                                  : "Newton solve"));
    mumps.set("gathered", chooseLinearSolve(s, {c.globalRows, c.ranks}).gathered);
  } else if (s.preconditioner == Preconditioner::mueLu) {
    p->set("Preconditioner Type", "MueLu");
    p->sublist("Preconditioner Types").set("MueLu", mueluParameters(s, c));
  } else if (s.preconditioner == Preconditioner::frosch) {
    p->set("Preconditioner Type", "FROSch");
    p->sublist("Preconditioner Types").set("FROSch", froschParameters(s, c));
  } else if (s.preconditioner == Preconditioner::ifpack2) {
    p->set("Preconditioner Type", "Ifpack2");
    p->sublist("Preconditioner Types").set("Ifpack2", ifpack2Parameters(s, c));
  } else {
    p->set("Preconditioner Type", "None");
  }
  return p;
}

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> directTangentSolver(const LinearSolverParameters &section,
                                                                              LinearSolverContext context) {
  LinearSolverParameters direct = section;
  direct.type = LinearSolverType::direct;
  direct.directSolver = DirectSolver::mumps;
  direct.directReuseIterations = 0; // each tangent is a new state's
  // Gathered where Newton's direct solve is (so that runs and restarts stay the same bit for bit),
  // else distributed (unless the deck gathers it).
  const bool gathered = chooseLinearSolve(section, {context.globalRows, context.ranks}).gathered;
  direct.directDistribution = gathered ? DirectDistribution::gathered : DirectDistribution::distributed;
  context.direct = true;
  return buildLinearSolver(direct, context);
}

namespace {
void registerPreconditioners(Stratimikos::DefaultLinearSolverBuilder &builder) {
  registerMueLu(builder);
  registerFrosch(builder);
  registerIfpack2(builder);
  using Base = Thyra::PreconditionerFactoryBase<double>;
  builder.setPreconditioningStrategyFactory(Teuchos::abstractFactoryStd<Base, MumpsPreconditionerFactory>(), "MUMPS");
}
} // namespace

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>>
buildLinearSolver(const LinearSolverParameters &section, const LinearSolverContext &context) {
  Stratimikos::DefaultLinearSolverBuilder builder;
  registerPreconditioners(builder);
  builder.setParameterList(stratimikosParameters(section, context));
  auto solver = builder.createLinearSolveStrategy("");
  makePreconditionerCollective(*solver);
  return solver;
}

Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>>
buildDisplacementPreconditioner(const LinearSolverParameters &section, const LinearSolverContext &context) {
  Stratimikos::DefaultLinearSolverBuilder builder;
  registerPreconditioners(builder);
  LinearSolverContext displacementBlock = context;
  displacementBlock.symmetric = true; // K at fixed pressure is the symmetric part of a symmetric tangent
  LinearSolverParameters block = section;
  block.directSolver = DirectSolver::mumps; // a preconditioner, which KLU2 through Amesos2 is not
  builder.setParameterList(stratimikosParameters(block, displacementBlock));
  return collectivePreconditioner(builder.createPreconditioningStrategy(""));
}

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> buildBlockKrylovSolver(const LinearSolverParameters &section) {
  LinearSolverParameters krylov = section;
  krylov.krylovMethod = KrylovMethod::gmres; // the block system is indefinite: no CG
  krylov.preconditioner = Preconditioner::none;
  krylov.type = LinearSolverType::iterative;
  Stratimikos::DefaultLinearSolverBuilder builder;
  builder.setParameterList(stratimikosParameters(krylov, {}));
  return builder.createLinearSolveStrategy("");
}

} // namespace glossa::solvers
