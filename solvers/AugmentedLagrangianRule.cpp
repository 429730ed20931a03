#include "solvers/AugmentedLagrangianRule.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace glossa::solvers {

AugmentedLagrangianRule::AugmentedLagrangianRule(const materials::VolumetricEnergy &physical, double kappaAL)
    : physical_(physical), kappaAL_(kappaAL) {
  if (!(kappaAL > 0.0) || !std::isfinite(kappaAL))
    throw std::invalid_argument("AugmentedLagrangianRule: kappa_AL must be positive and finite");
  const double kappa = physical.kappa();
  if (!(kappa > 0.0))
    throw std::invalid_argument("AugmentedLagrangianRule: the physical bulk modulus must be positive");
  if (std::isinf(kappa)) {
    kappaT_ = kappaAL;
    beta_ = 1.0;
  } else {
    // Written so that neither product overflows for kappa/kappa_AL up to 1e300.
    beta_ = 1.0 / (1.0 + kappaAL / kappa);
    kappaT_ = kappaAL * beta_;
  }
}

double AugmentedLagrangianRule::dilatationAtPressure(double p) const {
  const double kappa = physical_.kappa();
  if (std::isinf(kappa)) return 1.0;
  const double s = p / kappa;
  switch (physical_.form()) {
    case materials::VolumetricEnergy::Form::Quadratic:
      return 1.0 + s;
    case materials::VolumetricEnergy::Form::SimoTaylor:
      // kappa/2 (theta - 1/theta) = p  <=>  theta^2 - 2 s theta - 1 = 0, positive root.
      return s + std::sqrt(s * s + 1.0);
    case materials::VolumetricEnergy::Form::LogSquared: {
      // kappa ln(theta)/theta = p has a root in (0, e] only for s <= 1/e (U' is increasing there
      // and peaks at theta = e); beyond, the law cannot carry the pressure: report e.
      if (s >= 1.0 / std::exp(1.0)) return std::exp(1.0);
      double lo = std::numeric_limits<double>::min(), hi = std::exp(1.0);
      for (int k = 0; k < 200 && hi - lo > 4.0 * std::numeric_limits<double>::epsilon() * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        (std::log(mid) / mid < s ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
  }
  return 1.0;
}

}  // namespace glossa::solvers
