#pragma once
// What the simulation itself reads of the deck's "Linear solver" section, parsed once: the
// solver type, the Krylov tolerance, whether the solver lives for the whole run, and the names it
// reports. The section's full translation into Stratimikos is solvers/LinearSolverFactory's.

#include <string>

#include <Teuchos_ParameterList.hpp>

namespace glossa::solvers {

enum class LinearSolverType { automatic, iterative, direct };

struct LinearSolverChoice {
  LinearSolverType type = LinearSolverType::automatic;
  double tolerance = 1e-8;
  bool keptForTheRun = false; // MueLu reuse scope = run: one solver object across Newton solves
  std::string directSolver, preconditioner; // as the deck names them (summary.json)
};

LinearSolverChoice parseLinearSolverChoice(const Teuchos::ParameterList &section);

} // namespace glossa::solvers
