// The augmented-Lagrangian rule converges to the physical volumetric law: on a one-unknown model of
// an element (its dilatation resisted by the surrounding material with stiffness Ks under an
// applied pressure q), the Uzawa iteration with the series modulus in the "tangent" reaches the
// solution of U_phys'(theta) = q - Ks (theta - 1), found independently by bisection.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "solvers/incompressibility/AugmentedLagrangianRule.hpp"

using glossa::materials::VolumetricEnergy;
using glossa::solvers::AugmentedLagrangianRule;

namespace {
constexpr double kMu = 80.194e6;

// Root of the increasing function f on [lo, hi] by bisection.
template <class F>
double bisect(F f, double lo, double hi) {
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct Fixed {
  double theta, pressure;
  int iterations;
};

// Uzawa on the model: inner solve U_t'(theta) + Lambda = q - Ks (theta - 1) for theta, then
// Lambda <- beta p, until the rule's dilatation error is below tol.
Fixed uzawa(const VolumetricEnergy &physical, double kappaAL, double q, double Ks, double tol) {
  const AugmentedLagrangianRule rule(physical, kappaAL);
  const VolumetricEnergy tangent = physical.withKappa(rule.tangentKappa());
  double lambda = 0.0;
  for (int k = 1; k <= 200; ++k) {
    const double theta =
        bisect([&](double t) { return tangent.dU(t) + lambda - q + Ks * (t - 1.0); }, 0.05, 20.0);
    const double p = tangent.dU(theta) + lambda;
    if (rule.dilatationError(theta, p) < tol) return {theta, p, k};
    lambda = rule.nextMultiplier(p);
  }
  return {std::nan(""), std::nan(""), 200};
}
}  // namespace

TEST(AugmentedLagrangianRule, SeriesModulusAndItsIncompressibleLimit) {
  const double kappa = 5000.0 * kMu, kappaAL = 100.0 * kMu;
  const AugmentedLagrangianRule finite(VolumetricEnergy(VolumetricEnergy::Form::SimoTaylor, kappa), kappaAL);
  EXPECT_NEAR(finite.tangentKappa(), 1.0 / (1.0 / kappa + 1.0 / kappaAL), 1e-12 * kappaAL);
  EXPECT_NEAR(finite.beta(), 5000.0 / 5100.0, 1e-15);
  const AugmentedLagrangianRule exact(
      VolumetricEnergy(VolumetricEnergy::Form::SimoTaylor, std::numeric_limits<double>::infinity()), kappaAL);
  EXPECT_EQ(exact.tangentKappa(), kappaAL);
  EXPECT_EQ(exact.beta(), 1.0);
  EXPECT_EQ(exact.dilatationAtPressure(-4e8), 1.0);
  EXPECT_THROW(AugmentedLagrangianRule(VolumetricEnergy(VolumetricEnergy::Form::Quadratic, kappa), 0.0),
               std::invalid_argument);
}

TEST(AugmentedLagrangianRule, DilatationAtPressureInvertsThePhysicalLaw) {
  for (auto form : {VolumetricEnergy::Form::SimoTaylor, VolumetricEnergy::Form::LogSquared,
                    VolumetricEnergy::Form::Quadratic}) {
    const VolumetricEnergy U(form, 50.0 * kMu);
    const AugmentedLagrangianRule rule(U, 100.0 * kMu);
    for (double p : {-20.0 * kMu, -1.0 * kMu, 0.0, 0.3 * kMu, 15.0 * kMu}) {
      const double theta = rule.dilatationAtPressure(p);
      EXPECT_NEAR(U.dU(theta), p, 1e-10 * 50.0 * kMu) << static_cast<int>(form) << " p = " << p;
      EXPECT_NEAR(rule.dilatationError(theta, p), 0.0, 1e-12);
    }
  }
}

TEST(AugmentedLagrangianRule, UzawaReachesThePhysicalLawForFiniteKappa) {
  // nu = 0.4999 (kappa/mu = 5000) in the law, kappa_AL/mu = 100 in the tangent; a compressive
  // pressure of 5 mu against a surrounding stiffness of mu.
  const double q = -5.0 * kMu, Ks = kMu;
  for (auto form : {VolumetricEnergy::Form::SimoTaylor, VolumetricEnergy::Form::LogSquared,
                    VolumetricEnergy::Form::Quadratic}) {
    const VolumetricEnergy physical(form, 2.0 * kMu * 1.4999 / (3.0 * 0.0002));
    const double thetaRef = bisect([&](double t) { return physical.dU(t) - q + Ks * (t - 1.0); }, 0.05, 20.0);
    const Fixed r = uzawa(physical, 100.0 * kMu, q, Ks, 1e-13);
    EXPECT_NEAR(r.theta, thetaRef, 2e-13) << static_cast<int>(form);
    EXPECT_NEAR(r.pressure, physical.dU(thetaRef), 1e-8 * std::abs(q));
    EXPECT_LT(r.iterations, 12) << "the proximal iteration contracts by about Ks / kappa_AL per step";
    // The plain (wrong) rule Lambda <- p_e with the same tangent would converge to theta = 1.
    EXPECT_GT(std::abs(thetaRef - 1.0), 1e-4);
  }
}

TEST(AugmentedLagrangianRule, UzawaReachesIncompressibilityForInfiniteKappa) {
  const VolumetricEnergy physical(VolumetricEnergy::Form::SimoTaylor,
                                  std::numeric_limits<double>::infinity());
  const double q = -5.0 * kMu, Ks = kMu;
  const Fixed r = uzawa(physical, 100.0 * kMu, q, Ks, 1e-12);
  EXPECT_NEAR(r.theta, 1.0, 1e-12);
  EXPECT_NEAR(r.pressure, q, 1e-9 * std::abs(q));  // theta = 1: the structure carries nothing
}
