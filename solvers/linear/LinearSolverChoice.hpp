#pragma once
// Which linear solve a run gets: the deck's `Linear solver/type`, and for `type = auto` the rule
// that picks a direct or an iterative solve from the problem (its unknowns and the ranks that
// solve it) by the measured cost of each (doc/incompressibility.md, "Choosing direct or
// iterative"); and where a direct solve runs on several ranks. A symmetric or nonsymmetric tangent,
// a nearly incompressible or a controlled scene moved no measured crossover past the problem
// sizes on either side of it, so the rule does not read them. No Trilinos: unit-tested alone.

#include "solvers/parameters/LinearSolverParameters.hpp"

namespace glossa::solvers {

// What the rule looks at.
struct LinearProblem {
  long long unknowns = 0; // global rows of the tangent
  int ranks = 1;          // the ranks that solve it (a control group's, with --control-groups)
};

struct LinearSolveChoice {
  bool direct = false;
  // The direct solve factors on rank 0 alone, the entries gathered there (MumpsPreconditioner).
  bool gathered = false;
};

// The largest number of unknowns `type = auto` solves directly for this problem.
long long autoDirectLimit(const LinearSolverParameters &section, const LinearProblem &problem);

LinearSolveChoice chooseLinearSolve(const LinearSolverParameters &section, const LinearProblem &problem);

// Whether a controller's sensitivities (one tangent, a right-hand side per muscle group) are
// factored by MUMPS afresh: `sensitivity solve = direct`; auto where Newton's solve is MUMPS, and
// beside an iterative one up to kSensitivityDirectUpTo unknowns; never with `as Newton`.
constexpr long long kSensitivityDirectUpTo = 30000;
bool directSensitivitySolve(const LinearSolverParameters &section, const LinearProblem &problem);

} // namespace glossa::solvers
