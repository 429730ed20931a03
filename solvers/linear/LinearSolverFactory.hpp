#pragma once
// The linear solver of every Newton step, chosen in the deck's "Linear solver" section and built
// through Stratimikos: Belos CG (symmetric tangent) or GMRES, preconditioned by MueLu smoothed
// aggregation (rigid-body modes and coordinates supplied), FROSch two-level Schwarz, Ifpack2 alone,
// or none; or a direct solve: MUMPS as an exact preconditioner (solvers/linear/MumpsPreconditioner), or
// Amesos2 KLU2 for comparison. The preconditioner families' expensive template instantiations are
// each in a unit of their own (solvers/linear/PreconditionerRegistration.hpp).

#include <optional>
#include <string>
#include <Teuchos_ParameterList.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

#include "assembly/TpetraTypes.hpp"
#include "solvers/parameters/LinearSolverParameters.hpp"

namespace glossa::solvers {

struct LinearSolverContext {
  Teuchos::RCP<assembly::MultiVector> coordinates;    // per owned node, 3 columns
  Teuchos::RCP<assembly::MultiVector> rigidBodyModes; // per owned dof, 6 columns
  int ranks = 1;
  long long globalRows = 0;
  bool symmetric = true; // the tangent is symmetric (no follower loads yet)
  // The run's decision (LinearSolverPlan::direct), which the factory follows; empty: decided here
  // from the section (usesDirectSolve), as for a context built without a plan.
  std::optional<bool> direct;
};

// The section chooses a direct solve: type = direct, or auto where the rule of
// solvers/linear/LinearSolverChoice says the direct solve is the cheaper.
bool usesDirectSolve(const LinearSolverParameters &section, const LinearSolverContext &context);

// How long a Newton solver keeps its linear solver: the deck's `MueLu reuse scope` for a MueLu
// preconditioner; a Newton solve for the direct, FROSch, Ifpack2 and mixed block solves, which
// build theirs per Newton solve.
ReuseScope keptReuseScope(const LinearSolverParameters &section, const LinearSolverContext &context,
                          bool mixedBlockSolve);

// A run's linear solve, resolved once from the section and the problem: whether it is direct,
// how long Newton keeps it (keptReuseScope) and what the summary calls it.
struct LinearSolverPlan {
  bool direct = false;
  ReuseScope keptScope = ReuseScope::newtonSolve;
  std::string description; // "direct (MUMPS)", "iterative (MueLu)"
  // A controller's sensitivities are factored by MUMPS: the Newton solves' are, or `sensitivity
  // solve` chose it beside an iterative one (set by the run, which knows whether it is controlled).
  bool directSensitivities = false;
};
LinearSolverPlan planLinearSolver(const LinearSolverParameters &section, const LinearSolverContext &context,
                                  bool mixedBlockSolve);

// The Stratimikos parameter list the deck section stands for (exposed for tests and the docs).
Teuchos::RCP<Teuchos::ParameterList> stratimikosParameters(const LinearSolverParameters &section,
                                                           const LinearSolverContext &context);

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>>
buildLinearSolver(const LinearSolverParameters &section, const LinearSolverContext &context);

// MUMPS for a controller's sensitivities (Linear solver/sensitivity solve): a fresh factorisation of
// every tangent, which Newton's kept factors never stand in for; gathered onto rank 0 where the
// section's own direct solve would be, distributed over the ranks otherwise.
Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> directTangentSolver(const LinearSolverParameters &section,
                                                                              LinearSolverContext context);

// For the mixed block solve (solvers/linear/MixedBlockSolver): the preconditioner of the displacement
// block as the section says (MueLu, FROSch, Ifpack2 or none), and Belos GMRES with the section's
// tolerance, iteration limit and restart, which takes an external preconditioner.
Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>>
buildDisplacementPreconditioner(const LinearSolverParameters &section, const LinearSolverContext &context);
Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> buildBlockKrylovSolver(const LinearSolverParameters &section);

} // namespace glossa::solvers
