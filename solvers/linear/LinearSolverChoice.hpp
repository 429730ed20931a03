#pragma once
// Which linear solve a run gets: the deck's `Linear solver/type`, and for `type = auto` the rule
// that picks a direct or an iterative solve from the problem (its unknowns, the ranks that solve
// it, whether its tangent is symmetric) by the measured cost of each (doc/incompressibility.md,
// "Choosing direct or iterative"); and where a direct solve runs on several ranks. No Trilinos:
// the rule is unit-tested on its own.

#include "solvers/parameters/LinearSolverParameters.hpp"

namespace glossa::solvers {

// What the rule looks at.
struct LinearProblem {
  long long unknowns = 0; // global rows of the tangent
  int ranks = 1;          // the ranks that solve it (a control group's, with --control-groups)
  bool symmetric = true;  // a symmetric tangent (CG, LDL^T); otherwise GMRES and LU
};

struct LinearSolveChoice {
  bool direct = false;
  // The direct solve factors on rank 0 alone, the entries gathered there (MumpsPreconditioner).
  bool gathered = false;
};

// The largest number of unknowns `type = auto` solves directly for this problem.
long long autoDirectLimit(const LinearSolverParameters &section, const LinearProblem &problem);

LinearSolveChoice chooseLinearSolve(const LinearSolverParameters &section, const LinearProblem &problem);

} // namespace glossa::solvers
