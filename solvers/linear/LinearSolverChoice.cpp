#include "solvers/linear/LinearSolverChoice.hpp"

namespace glossa::solvers {

long long autoDirectLimit(const LinearSolverParameters &s, const LinearProblem &) { return s.directUpTo; }

LinearSolveChoice chooseLinearSolve(const LinearSolverParameters &s, const LinearProblem &p) {
  LinearSolveChoice c;
  if (s.type == LinearSolverType::automatic)
    c.direct = p.unknowns > 0 && p.unknowns <= autoDirectLimit(s, p);
  else
    c.direct = s.type == LinearSolverType::direct;
  const bool gather = s.directDistribution == DirectDistribution::gathered ||
                      (s.directDistribution == DirectDistribution::automatic && s.type == LinearSolverType::automatic);
  c.gathered = p.ranks > 1 && gather;
  return c;
}

} // namespace glossa::solvers
