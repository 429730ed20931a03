#include "solvers/nonlinear/InexactNewtonForcing.hpp"

#include <algorithm>
#include <cmath>

namespace glossa::solvers {

InexactNewtonForcing::InexactNewtonForcing(double minimum, double maximum, double residualTolerance)
    : minimum_(minimum), maximum_(std::max(minimum, maximum)), residualTolerance_(residualTolerance) {}

double InexactNewtonForcing::first() { return last_ = maximum_; }

double InexactNewtonForcing::next(double residual, double previousResidual) {
  double eta = previousResidual > 0.0 ? kGamma * std::pow(residual / previousResidual, kAlpha) : maximum_;
  const double fromLast = kGamma * std::pow(last_, kAlpha);
  if (fromLast > 0.1) eta = std::max(eta, fromLast);
  if (residual > 0.0 && residualTolerance_ > 0.0) eta = std::max(eta, 0.5 * residualTolerance_ / residual);
  return last_ = std::clamp(eta, minimum_, maximum_);
}

} // namespace glossa::solvers
