#include "solvers/linear/LinearSolverChoice.hpp"

namespace glossa::solvers {

// Under auto a direct solve on several ranks is gathered onto rank 0: its cost is one rank's, while
// the iterative solve shares its work among the ranks. A sparse factorisation of a 3D mesh costs
// about n^2 (nested dissection: the top separator has n^(2/3) unknowns, its dense factor n^2
// flops), a multigrid-preconditioned solve about n, so where they cost the same on one rank, n1,
// they do on R ranks at n1 / R. Measured on 2 ranks (doc/incompressibility.md, "Choosing direct or
// iterative"): the direct solve is the faster at 2,838 unknowns and the iterative one at 6,591.
long long autoDirectLimit(const LinearSolverParameters &s, const LinearProblem &p) {
  return p.ranks > 1 ? s.directUpTo / p.ranks : s.directUpTo;
}

LinearSolveChoice chooseLinearSolve(const LinearSolverParameters &s, const LinearProblem &p) {
  LinearSolveChoice c;
  if (s.type == LinearSolverType::automatic)
    c.direct = p.unknowns > 0 && p.unknowns <= autoDirectLimit(s, p);
  else
    c.direct = s.type == LinearSolverType::direct;
  // auto gathers so that runs on several ranks stay deterministic (restarts end byte for byte).
  const bool gather = s.directDistribution == DirectDistribution::gathered ||
                      (s.directDistribution == DirectDistribution::automatic && s.type == LinearSolverType::automatic);
  c.gathered = p.ranks > 1 && gather;
  return c;
}

} // namespace glossa::solvers
