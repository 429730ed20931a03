#include "solvers/stepping/GeneralizedAlpha.hpp"

#include <stdexcept>
#include <string>

namespace glossa::solvers {

GeneralizedAlpha::GeneralizedAlpha(double rho) {
  if (!(rho >= 0.0 && rho <= 1.0))
    throw std::invalid_argument("generalized-alpha: spectral radius " + std::to_string(rho) + " is not in [0, 1]");
  alphaM_ = (2.0 * rho - 1.0) / (rho + 1.0);
  alphaF_ = rho / (rho + 1.0);
  gamma_ = 0.5 - alphaM_ + alphaF_;
  const double s = 1.0 - alphaM_ + alphaF_;
  beta_ = 0.25 * s * s;
}

GeneralizedAlpha::Step GeneralizedAlpha::step(double dt) const {
  if (!(dt > 0.0)) throw std::invalid_argument("generalized-alpha: step " + std::to_string(dt) + " is not positive");
  Step s{};
  s.dt = dt;
  s.c0 = 1.0 / (beta_ * dt * dt);
  s.c1 = 1.0 / (beta_ * dt);
  s.c2 = 0.5 / beta_ - 1.0;
  s.vOld = (1.0 - gamma_) * dt;
  s.vNew = gamma_ * dt;
  const double f = 1.0 - alphaF_; // in [1/2, 1]
  s.newAcceleration = (1.0 - alphaM_) / f;
  s.oldAcceleration = alphaM_ / f;
  s.oldForces = alphaF_ / f;
  s.massFactor = s.newAcceleration * s.c0;
  s.dampingFactor = s.vNew * s.c0;
  return s;
}

} // namespace glossa::solvers
