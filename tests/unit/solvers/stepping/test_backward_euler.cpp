// Backward Euler on one undamped oscillator u'' + w^2 u = 0, stepped with the coefficients the run
// uses, against the closed form of backward Euler on the first-order system (u, v): one step
// multiplies the mode by 1/(1 - i W), W = w dt. So
// - the period is lengthened by W/atan(W) - 1 ~ W^2/3: second order, four times the trapezoidal
//   rule's W^2/12;
// - the amplitude falls by 1/sqrt(1 + W^2) a step, about pi W of its log a period: first order,
//   which is what makes the method first order (the global error halves with the step);
// - the spectral radius tends to 0 as W grows (L-stable: the unresolved modes of a stiff problem
//   are gone after a step).

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "solvers/stepping/BackwardEuler.hpp"
#include "tests/unit/solvers/stepping/OscillatorStep.hpp"

namespace glossa::solvers {
namespace {

using test::amplification;
using test::oscillatorStep;
using test::principalRoot;

TEST(BackwardEuler, StepIsTheClosedFormOfBackwardEuler) {
  for (double Omega : {0.01, 0.1, 0.5, 2.0, 50.0}) {
    const std::complex<double> l = principalRoot(amplification(backwardEulerStep(Omega), 1.0));
    const std::complex<double> exact = 1.0 / std::complex<double>(1.0, -Omega);
    EXPECT_NEAR(std::abs(l - exact), 0.0, 1e-12) << "Omega " << Omega;
  }
  EXPECT_THROW(backwardEulerStep(0.0), std::invalid_argument);
  EXPECT_THROW(backwardEulerStep(-1e-3), std::invalid_argument);
}

TEST(BackwardEuler, PeriodErrorIsSecondOrderAndAmplitudeLossFirstOrder) {
  double period[2], loss[2];
  const double Omegas[2] = {0.04, 0.02};
  for (int i = 0; i < 2; ++i) {
    const auto s = backwardEulerStep(Omegas[i]);
    period[i] = test::periodError(s);
    const std::complex<double> l = principalRoot(amplification(s, 1.0));
    loss[i] = -std::log(std::abs(l)) * 2.0 * M_PI / std::arg(l); // log-amplitude lost a period
  }
  EXPECT_NEAR(period[0], Omegas[0] / std::atan(Omegas[0]) - 1.0, 1e-12);
  EXPECT_NEAR(std::log(period[0] / period[1]) / std::log(2.0), 2.0, 0.01);
  EXPECT_NEAR(loss[0], M_PI * Omegas[0], 0.01 * M_PI * Omegas[0]);
  EXPECT_NEAR(std::log(loss[0] / loss[1]) / std::log(2.0), 1.0, 0.01);
}

TEST(BackwardEuler, GlobalErrorIsFirstOrder) {
  // One period from u = 1 at rest, against cos(w t): the error at the end halves with the step.
  const double omega = 2.0 * M_PI;
  double error[3];
  const int steps[3] = {200, 400, 800};
  for (int i = 0; i < 3; ++i) {
    const auto s = backwardEulerStep(1.0 / steps[i]);
    Eigen::Vector3d x(1.0, 0.0, -omega * omega);
    for (int n = 0; n < steps[i]; ++n) x = oscillatorStep(s, omega * omega, 0.0, x);
    error[i] = std::abs(x(0) - 1.0);
  }
  EXPECT_NEAR(std::log(error[0] / error[1]) / std::log(2.0), 1.0, 0.05);
  EXPECT_NEAR(std::log(error[1] / error[2]) / std::log(2.0), 1.0, 0.03);
}

TEST(BackwardEuler, UnresolvedModesGoAtOnce) {
  // L-stability: the spectral radius is 1/sqrt(1 + W^2) (the acceleration's own root is 0).
  for (double Omega : {1e2, 1e4, 1e6})
    EXPECT_NEAR(test::spectralRadius(amplification(backwardEulerStep(Omega), 1.0)), 1.0 / std::sqrt(1.0 + Omega * Omega),
                1e-9 / Omega)
        << "Omega " << Omega;
}

} // namespace
} // namespace glossa::solvers
