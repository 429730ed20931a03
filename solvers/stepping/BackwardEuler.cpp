#include "solvers/stepping/BackwardEuler.hpp"

#include <stdexcept>
#include <string>

namespace glossa::solvers {

GeneralizedAlpha::Step backwardEulerStep(double dt) {
  if (!(dt > 0.0)) throw std::invalid_argument("backward Euler: step " + std::to_string(dt) + " is not positive");
  GeneralizedAlpha::Step s{};
  s.dt = dt;
  s.c0 = 1.0 / (dt * dt);
  s.c1 = 1.0 / dt;
  s.c2 = 0.0;
  // v_{n+1} = v_n + dt a_{n+1}: the old acceleration has no weight.
  s.vOld = 0.0;
  s.vNew = dt;
  // The balance at t_{n+1} alone: no share of the last step's inertia or forces.
  s.newAcceleration = 1.0;
  s.oldAcceleration = 0.0;
  s.oldForces = 0.0;
  s.massFactor = s.c0;
  s.dampingFactor = s.vNew * s.c0;
  return s;
}

} // namespace glossa::solvers
