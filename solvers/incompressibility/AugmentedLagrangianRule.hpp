#pragma once
// The augmented-Lagrangian (Uzawa) rule for a physical volumetric law of finite or infinite bulk
// modulus (doc/incompressibility.md, "Physical kappa and kappa_AL"). Pure functions, no Trilinos.
//
// The physical law is U_phys with bulk modulus kappa (kappa = inf: exact incompressibility). The
// Uzawa iteration is the proximal-point method on the pressure with step kappa_AL: with the
// element carrying p = U_t'(theta) + Lambda, where U_t is the same form as U_phys with the series
// modulus
//     kappa_t = kappa kappa_AL / (kappa + kappa_AL)          (-> kappa_AL for kappa = inf),
// the multiplier update is
//     Lambda <- beta p_e,   beta = kappa / (kappa + kappa_AL)  (-> 1: Lambda <- Lambda + U_AL'(theta)).
// Its fixed point is p_e = U_phys'(theta_e): (1 - beta) Lambda = beta U_t'(theta) and U' is linear
// in kappa, so p = U_t'(theta) (kappa + kappa_AL) / kappa_AL = U_phys'(theta).

#include "materials/VolumetricEnergy.hpp"

namespace glossa::solvers {

class AugmentedLagrangianRule {
 public:
  // `physical`: the material's volumetric law (kappa may be +inf); kappaAL > 0.
  AugmentedLagrangianRule(const materials::VolumetricEnergy &physical, double kappaAL);

  double tangentKappa() const { return kappaT_; }
  double beta() const { return beta_; }
  // Lambda of the next Uzawa solve from the element pressure p_e = U_t'(theta) + Lambda.
  double nextMultiplier(double elementPressure) const { return beta_ * elementPressure; }
  // The dilatation the physical law assigns to pressure p (U_phys'(theta) = p; 1 for kappa = inf).
  double dilatationAtPressure(double p) const { return physical_.dilatationAtPressure(p); }
  // The Uzawa stopping measure: |theta - theta_phys(p_e)|, zero at the fixed point.
  double dilatationError(double theta, double elementPressure) const {
    const double d = theta - dilatationAtPressure(elementPressure);
    return d < 0.0 ? -d : d;
  }

 private:
  materials::VolumetricEnergy physical_;
  double kappaAL_, kappaT_, beta_;
};

}  // namespace glossa::solvers
