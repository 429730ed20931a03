#include "solvers/incompressibility/AugmentedLagrangianRule.hpp"

#include <cmath>
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

}  // namespace glossa::solvers
