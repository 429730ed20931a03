#pragma once
// The deck's "Linear solver" section, declared and parsed once: the solver type, the Krylov
// method and its limits, the preconditioner and each preconditioner's settings. Translated into
// Stratimikos by solvers/linear/LinearSolverFactory.

#include <string>

#include <Teuchos_ParameterList.hpp>

namespace glossa::solvers {

enum class LinearSolverType { automatic, iterative, direct };
enum class DirectSolver { mumps, klu2 };
// MUMPS on several ranks: on rank 0 alone with the entries gathered there, or on every rank.
enum class DirectDistribution { automatic, gathered, distributed };
enum class KrylovMethod { automatic, cg, gmres };
enum class Preconditioner { mueLu, frosch, ifpack2, none };
enum class MueLuSmoother { chebyshev, symmetricGaussSeidel, nodeBlockGaussSeidel, vertexPatch };
enum class VertexPatchLevels { finest, all };
enum class FroschCoarseSpace { gdsw, rgdsw };
enum class Ifpack2Type { symmetricGaussSeidel, chebyshev, ilut };
enum class EigenvalueMethod { lanczos, power };
// How long a MueLu hierarchy, or MUMPS factors, reused between Newton iterations live before they
// are rebuilt.
enum class ReuseScope { newtonSolve, step, run };
// A controller's sensitivities (also the responses the GA's candidates start along): with the
// Newton solves' solver, or factored afresh by MUMPS (LinearSolverChoice: directSensitivitySolve).
enum class SensitivitySolve { automatic, asNewton, direct };

// The defaults are the declared ones (linearSolverParameters()).
struct LinearSolverParameters {
  LinearSolverType type = LinearSolverType::automatic;
  DirectSolver directSolver = DirectSolver::mumps;
  int directUpTo = 8000;
  DirectDistribution directDistribution = DirectDistribution::automatic;
  std::string directOrdering = "auto"; // MUMPS's fill-reducing ordering, the deck's word handed to it as it is
  int directReuseIterations = 10;
  ReuseScope directReuseScope = ReuseScope::step;
  SensitivitySolve sensitivitySolve = SensitivitySolve::automatic;
  KrylovMethod krylovMethod = KrylovMethod::automatic;
  Preconditioner preconditioner = Preconditioner::mueLu;
  FroschCoarseSpace froschCoarseSpace = FroschCoarseSpace::gdsw;
  int froschOverlap = 1;
  double tolerance = 1e-6;
  int maximumIterations = 2000;
  int gmresRestart = 200;
  MueLuSmoother mueLuSmoother = MueLuSmoother::chebyshev;
  int smootherDegree = 6;
  VertexPatchLevels vertexPatchLevels = VertexPatchLevels::finest;
  int patchSweeps = 1;
  EigenvalueMethod chebyshevEigenvalueMethod = EigenvalueMethod::lanczos;
  int chebyshevEigenvalueIterations = 0; // 0: the method's default (LinearSolverFactory)
  double chebyshevEigenvalueRatio = 100.0;
  std::string mueLuReuse = "RAP"; // MueLu's own "reuse: type" word, handed to it as it is
  ReuseScope reuseScope = ReuseScope::step;
  int coarseSize = 2000;
  Ifpack2Type ifpack2Type = Ifpack2Type::symmetricGaussSeidel;
  bool verbose = false;
  // The deck's words, for summary.json.
  std::string directSolverName = "MUMPS", preconditionerName = "MueLu";
};

Teuchos::ParameterList linearSolverParameters();
LinearSolverParameters parseLinearSolverParameters(const Teuchos::ParameterList &section);

} // namespace glossa::solvers
