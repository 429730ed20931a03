#include "materials/ActivationDynamics.hpp"

#include <cmath>
#include <stdexcept>

namespace glossa::materials {

ActivationDynamics::ActivationDynamics(ActivationParameters parameters) : p_(parameters) {
  if (!(p_.tauR > 0.0) || !std::isfinite(p_.tauR))
    throw std::invalid_argument("activation: tau_R must be > 0");
  if (!(p_.tauF > 0.0) || !std::isfinite(p_.tauF))
    throw std::invalid_argument("activation: tau_F must be > 0");
  if (!(p_.alphaMin >= 0.0 && p_.alphaMin < 1.0))
    throw std::invalid_argument("activation: alpha_min must be in [0, 1)");
}

double ActivationDynamics::step(double alphaOld, double u, double dt) const {
  if (!(u >= 0.0 && u <= 1.0)) throw std::invalid_argument("activation: neural input u must be in [0, 1]");
  if (!(dt > 0.0) || !std::isfinite(dt)) throw std::invalid_argument("activation: dt must be > 0");
  if (!(alphaOld >= 0.0 && alphaOld <= 1.0))
    throw std::invalid_argument("activation: alpha must be in [0, 1]");
  const double rise = u / p_.tauR, fall = (1.0 - u) / p_.tauF;
  return (alphaOld + dt * (rise + p_.alphaMin * fall)) / (1.0 + dt * (rise + fall));
}

double ActivationDynamics::stepInputDerivative(double alphaOld, double u, double dt) const {
  step(alphaOld, u, dt); // validates the arguments
  // alpha = N / D with N, D affine in u: d alpha / du = (N' D - N D') / D^2.
  const double N = alphaOld + dt * (u / p_.tauR + p_.alphaMin * (1.0 - u) / p_.tauF);
  const double D = 1.0 + dt * (u / p_.tauR + (1.0 - u) / p_.tauF);
  const double dN = dt * (1.0 / p_.tauR - p_.alphaMin / p_.tauF), dD = dt * (1.0 / p_.tauR - 1.0 / p_.tauF);
  return (dN * D - N * dD) / (D * D);
}

double ActivationDynamics::exact(double alpha0, double u, double t) const {
  const double rise = u / p_.tauR, fall = (1.0 - u) / p_.tauF;
  const double k = rise + fall;
  const double alphaInf = (rise + p_.alphaMin * fall) / k;
  return alphaInf + (alpha0 - alphaInf) * std::exp(-k * t);
}

}  // namespace glossa::materials
