#include "solvers/linear/LinearSolverChoice.hpp"

#include <algorithm>

namespace glossa::solvers {

// Measured on 1 and 2 ranks (doc/incompressibility.md, "Choosing direct or iterative"): MUMPS beat
// MueLu on 2 ranks as on one up to the step-44 block at 12 per side (6,591 unknowns: 8.2 s
// distributed, 12.9 s gathered, 28.5 s iterative), so the limit does not shrink with the ranks.
long long autoDirectLimit(const LinearSolverParameters &s, const LinearProblem &) { return s.directUpTo; }

LinearSolveChoice chooseLinearSolve(const LinearSolverParameters &s, const LinearProblem &p) {
  LinearSolveChoice c;
  const bool automatic = s.type == LinearSolverType::automatic;
  c.direct = automatic ? p.unknowns > 0 && p.unknowns <= autoDirectLimit(s, p) : s.type == LinearSolverType::direct;
  // Gathered, the factorisation costs one rank's, while a distributed one is shared (and its last
  // bits vary from run to run): auto gathers up to 'direct up to' / R unknowns, where the
  // factorisation is cheap beside the assembly (2,838 unknowns on 2 ranks: 2.45 s gathered, 2.39 s
  // distributed), so that those runs and their restarts are the same bit for bit.
  const bool small = p.unknowns <= s.directUpTo / std::max(p.ranks, 1);
  const bool gather = s.directDistribution == DirectDistribution::gathered ||
                      (s.directDistribution == DirectDistribution::automatic && automatic && small);
  c.gathered = p.ranks > 1 && gather;
  return c;
}

// Measured on the medium tongue (20,097 unknowns, 2 ranks, the supine gradient deck's first 8
// steps: doc/performance.md): a sensitivity's 11 right-hand sides took 3.9 s with MueLu and Block
// GMRES against 2.0 s factored by MUMPS (1.45 s of it the factorisation). With one right-hand
// side, or far above that size, the Krylov solve is the cheaper; the larger meshes are not
// measured, hence the limit near the measured size.
bool directSensitivitySolve(const LinearSolverParameters &s, const LinearProblem &p) {
  if (s.sensitivitySolve != SensitivitySolve::automatic) return s.sensitivitySolve == SensitivitySolve::direct;
  const LinearSolveChoice newton = chooseLinearSolve(s, p);
  return newton.direct ? s.directSolver == DirectSolver::mumps : p.unknowns <= kSensitivityDirectUpTo;
}

} // namespace glossa::solvers
