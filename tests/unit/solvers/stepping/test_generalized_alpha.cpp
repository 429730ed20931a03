// Generalized-alpha on one undamped oscillator u'' + w^2 u = 0, stepped with the coefficients the
// run uses, against Chung & Hulbert (1993) and the trapezoidal rule's known properties:
// - the parameters of rho_inf = 1 (Newmark's trapezoidal rule) and rho_inf = 0 (eq. 25);
// - rho_inf = 1: the discrete frequency is exactly 2 atan(w dt / 2) / dt and the amplitude is
//   kept (no numerical dissipation, energy conserved);
// - every rho_inf: the period error is second order in dt (log-log slope 2);
// - the spectral radius of the step's amplification matrix tends to rho_inf as w dt grows, and a
//   resolved mode's amplitude loss per step is of fourth order in w dt.

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "solvers/stepping/GeneralizedAlpha.hpp"
#include "tests/unit/solvers/stepping/OscillatorStep.hpp"

namespace glossa::solvers {
namespace {

using test::oscillatorStep;
using test::principalRoot;
using test::spectralRadius;

Eigen::Matrix3d amplification(const GeneralizedAlpha &scheme, double omega, double dt) {
  return test::amplification(scheme.step(dt), omega);
}

double periodError(const GeneralizedAlpha &scheme, double Omega) { return test::periodError(scheme.step(Omega)); }

TEST(GeneralizedAlpha, ParametersOfTheLimitCases) {
  const GeneralizedAlpha trapezoidal(1.0);
  EXPECT_DOUBLE_EQ(trapezoidal.alphaM(), 0.5);
  EXPECT_DOUBLE_EQ(trapezoidal.alphaF(), 0.5);
  EXPECT_DOUBLE_EQ(trapezoidal.gamma(), 0.5);
  EXPECT_DOUBLE_EQ(trapezoidal.beta(), 0.25);
  const GeneralizedAlpha annihilating(0.0);
  EXPECT_DOUBLE_EQ(annihilating.alphaM(), -1.0);
  EXPECT_DOUBLE_EQ(annihilating.alphaF(), 0.0);
  EXPECT_DOUBLE_EQ(annihilating.gamma(), 1.5);
  EXPECT_DOUBLE_EQ(annihilating.beta(), 1.0);
  EXPECT_THROW(GeneralizedAlpha(1.01), std::invalid_argument);
  EXPECT_THROW(GeneralizedAlpha(-0.1), std::invalid_argument);
  EXPECT_THROW(trapezoidal.step(0.0), std::invalid_argument);
}

TEST(GeneralizedAlpha, TrapezoidalRuleHasTheKnownFrequencyAndNoDissipation) {
  const GeneralizedAlpha scheme(1.0);
  for (double Omega : {0.01, 0.1, 0.5, 2.0}) {
    const std::complex<double> l = principalRoot(amplification(scheme, 1.0, Omega));
    EXPECT_NEAR(std::abs(l), 1.0, 1e-12) << "Omega " << Omega;
    EXPECT_NEAR(std::arg(l), 2.0 * std::atan(0.5 * Omega), 1e-12) << "Omega " << Omega;
  }
  // The energy (1/2)(v^2 + w^2 u^2) over 100 periods at 20 steps a period: kept to round-off.
  const double omega = 2.0 * M_PI, dt = 1.0 / 20.0;
  const auto s = scheme.step(dt);
  Eigen::Vector3d x(0.0, 1.0, 0.0);
  for (int n = 0; n < 2000; ++n) x = oscillatorStep(s, omega * omega, 0.0, x);
  EXPECT_NEAR(0.5 * (x(1) * x(1) + omega * omega * x(0) * x(0)), 0.5, 1e-12);
}

TEST(GeneralizedAlpha, PeriodErrorIsSecondOrderForEverySpectralRadius) {
  for (double rho : {1.0, 0.9, 0.5, 0.0}) {
    const GeneralizedAlpha scheme(rho);
    const double e1 = periodError(scheme, 0.04), e2 = periodError(scheme, 0.02);
    EXPECT_GT(e1, 0.0) << "rho_inf " << rho; // the numerical period is longer
    EXPECT_NEAR(std::log(e1 / e2) / std::log(2.0), 2.0, 0.02) << "rho_inf " << rho;
  }
}

TEST(GeneralizedAlpha, SpectralRadiusTendsToRhoInfinity) {
  for (double rho : {1.0, 0.8, 0.5, 0.2, 0.0}) {
    const GeneralizedAlpha scheme(rho);
    // At rho_inf = 0 the three roots meet at 0 and part as (1/Omega^2)^(1/3): Omega = 1e9 puts
    // them within 1e-6 of their limit.
    EXPECT_NEAR(spectralRadius(amplification(scheme, 1.0, 1e9)), rho, 1e-4) << "rho_inf " << rho;
  }
}

TEST(GeneralizedAlpha, ResolvedModesLoseAmplitudeOnlyAtHighOrder) {
  // Second-order accuracy: the algorithmic damping ratio is O(Omega^3), so a step's amplitude
  // loss -ln|lambda| = damping ratio x Omega is O(Omega^4) for rho_inf < 1 (and 0 at rho_inf = 1).
  for (double rho : {0.8, 0.5, 0.0}) {
    const GeneralizedAlpha scheme(rho);
    const double l1 = -std::log(std::abs(principalRoot(amplification(scheme, 1.0, 0.04))));
    const double l2 = -std::log(std::abs(principalRoot(amplification(scheme, 1.0, 0.02))));
    EXPECT_GT(l2, 0.0) << "rho_inf " << rho;
    EXPECT_NEAR(std::log(l1 / l2) / std::log(2.0), 4.0, 0.05) << "rho_inf " << rho;
  }
}

} // namespace
} // namespace glossa::solvers
