#include <gtest/gtest.h>

#include <cmath>

#include "materials/ActivationDynamics.hpp"

using namespace glossa::materials;

// doc/materials.md's closed forms for u = 1 and u = 0, and the backward-Euler equation for any u.
TEST(ActivationDynamics, BackwardEulerClosedForms) {
  const ActivationDynamics a;  // tau_R = tau_F = 150 ms, alpha_min = 0
  EXPECT_EQ(a.parameters().tauR, 0.150);
  EXPECT_EQ(a.parameters().tauF, 0.150);
  EXPECT_EQ(a.parameters().alphaMin, 0.0);
  const double dt = 0.005;
  EXPECT_NEAR(a.step(0.3, 1.0, dt), (0.3 * 0.150 + dt) / (0.150 + dt), 1e-15);
  EXPECT_NEAR(a.step(0.3, 0.0, dt), (0.3 * 0.150 + dt * 0.0) / (0.150 + dt), 1e-15);
  const ActivationDynamics b({0.1, 0.3, 0.05});
  EXPECT_NEAR(b.step(0.6, 0.0, dt), (0.6 * 0.3 + dt * 0.05) / (0.3 + dt), 1e-15);
  for (double u : {0.0, 0.25, 0.7, 1.0})
    for (double alphaOld : {0.05, 0.5, 1.0}) {
      const double alpha = b.step(alphaOld, u, dt);
      const double rhs = (1 - alpha) * u / 0.1 + (0.05 - alpha) * (1 - u) / 0.3;
      EXPECT_NEAR((alpha - alphaOld) / dt, rhs, 1e-12);
    }
}

// Unconditionally stable: alpha stays in [alpha_min, 1] and tends to the fixed point for any dt.
TEST(ActivationDynamics, StableForAnyStep) {
  const ActivationDynamics a({0.15, 0.05, 0.1});
  for (double dt : {1e-5, 1e-3, 0.1, 100.0}) {
    double alpha = 0.1;
    for (int n = 0; n < 50; ++n) {
      alpha = a.step(alpha, n % 7 < 4 ? 1.0 : 0.0, dt);
      EXPECT_GE(alpha, 0.1 - 1e-15);
      EXPECT_LE(alpha, 1.0);
    }
  }
  const double u = 0.4, fixedPoint = (u / 0.15 + 0.1 * (1 - u) / 0.05) / (u / 0.15 + (1 - u) / 0.05);
  EXPECT_NEAR(a.step(0.3, u, 1e6), fixedPoint, 1e-6);
  EXPECT_NEAR(a.exact(0.3, u, 100.0), fixedPoint, 1e-12);
}

// u = 1 from rest: alpha(t) = 1 - exp(-t/tau_R). Backward Euler gives 1 - (1 + dt/tau_R)^-n, whose
// error lies in [0, dt/(2 e tau_R) (1 + dt/tau_R)] and halves with dt (first order).
TEST(ActivationDynamics, RiseConvergesFirstOrderToTheExactSolution) {
  const ActivationDynamics a;
  const double tau = 0.150;
  double previousError = 0;
  for (double dt : {0.010, 0.005, 0.0025, 0.00125}) {
    double alpha = 0.0, maxError = 0.0;
    for (int n = 1; n * dt <= 0.5 + 1e-12; ++n) {
      alpha = a.step(alpha, 1.0, dt);
      const double exact = 1.0 - std::exp(-n * dt / tau);
      EXPECT_NEAR(a.exact(0.0, 1.0, n * dt), exact, 1e-15);
      EXPECT_LE(alpha, exact + 1e-15);  // backward Euler lags the exact rise
      maxError = std::max(maxError, exact - alpha);
    }
    EXPECT_LE(maxError, dt / (2 * std::exp(1.0) * tau) * (1 + dt / tau));
    if (previousError > 0) EXPECT_NEAR(previousError / maxError, 2.0, 0.1);
    previousError = maxError;
  }
}

TEST(ActivationDynamics, RejectsInvalidInput) {
  EXPECT_THROW(ActivationDynamics({0.0, 0.15, 0.0}), std::invalid_argument);
  EXPECT_THROW(ActivationDynamics({0.15, -1.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(ActivationDynamics({0.15, 0.15, 1.0}), std::invalid_argument);
  const ActivationDynamics a;
  EXPECT_THROW(a.step(0.5, 1.5, 0.01), std::invalid_argument);
  EXPECT_THROW(a.step(0.5, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(a.step(1.5, 1.0, 0.01), std::invalid_argument);
  EXPECT_DOUBLE_EQ(fractionOfFullMuscleResponse(0.1, 0.5), 0.05);
}

// The input derivative of a step against central differences (one-sided at the ends of [0, 1]),
// with unequal time constants so that it depends on u.
TEST(ActivationDynamics, StepInputDerivativeMatchesFiniteDifferences) {
  const ActivationDynamics a({0.1, 0.3, 0.05});
  const double h = 1e-6;
  for (double dt : {0.001, 0.01, 0.2})
    for (double alphaOld : {0.05, 0.4, 1.0})
      for (double u : {0.0, 0.3, 0.8, 1.0}) {
        const double up = std::min(1.0, u + h), um = std::max(0.0, u - h);
        const double fd = (a.step(alphaOld, up, dt) - a.step(alphaOld, um, dt)) / (up - um);
        EXPECT_NEAR(a.stepInputDerivative(alphaOld, u, dt), fd, 1e-6 * (1.0 + std::abs(fd)))
            << "dt " << dt << " alpha " << alphaOld << " u " << u;
      }
  EXPECT_THROW(a.stepInputDerivative(0.5, 1.5, 0.01), std::invalid_argument);
}
