#pragma once
// The deck's "Nonlinear solver" section, declared and parsed once: Newton's iteration limit,
// tolerances, forcing term and line search (solvers/nonlinear/NewtonSolver).

#include <Teuchos_ParameterList.hpp>

namespace glossa::solvers {

enum class ForcingTerm { constant, type1, type2 };
enum class LineSearch { fullStep, guardedFullStep, backtrack, polynomial };

struct NewtonParameters {
  int maximumIterations = 25;
  double residualTolerance = 1e-8; // relative to the load
  double updateTolerance = 1e-6;   // ||dx|| relative to ||x|| (2-norms)
  ForcingTerm forcing = ForcingTerm::type2;
  LineSearch lineSearch = LineSearch::fullStep;
};

Teuchos::ParameterList nonlinearSolverParameters();
NewtonParameters parseNewtonParameters(const Teuchos::ParameterList &section);

} // namespace glossa::solvers
