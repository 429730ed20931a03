// The Krylov tolerance of each Newton iteration (solvers/nonlinear/InexactNewtonForcing): Eisenstat-Walker
// choice 2 with NOX's constants and safeguard, and the bound that keeps the last linear solve of
// a Newton solve from asking more than the residual test needs (Kelley 1995, section 6.3).
#include <gtest/gtest.h>

#include <cmath>

#include "solvers/nonlinear/InexactNewtonForcing.hpp"

using glossa::solvers::InexactNewtonForcing;

TEST(InexactNewtonForcing, FirstSolveTakesTheCeiling) {
  InexactNewtonForcing forcing(1e-6, 1e-2, 0.0);
  EXPECT_EQ(forcing.first(), 1e-2);
}

TEST(InexactNewtonForcing, ChoiceTwoFollowsTheResidualRatio) {
  InexactNewtonForcing forcing(1e-6, 1e-2, 1e-12);
  forcing.first();
  // 0.9 (1e-2)^1.5 = 9e-4; the previous tolerance's 0.9 (1e-2)^1.5 = 9e-4 is below 0.1.
  EXPECT_NEAR(forcing.next(1e-2, 1.0), 9e-4, 1e-18);
}

TEST(InexactNewtonForcing, ASuddenDropIsNotTrustedAfterALooseSolve) {
  InexactNewtonForcing forcing(1e-6, 0.9, 0.0);
  forcing.first();
  // The ratio asks 0.9 (1e-3)^1.5 = 2.8e-5, the previous 0.9 keeps 0.9 * 0.9^1.5 = 0.768.
  EXPECT_NEAR(forcing.next(1e-3, 1.0), 0.9 * std::pow(0.9, 1.5), 1e-15);
}

TEST(InexactNewtonForcing, DoesNotAskMoreThanTheResidualTestNeeds) {
  InexactNewtonForcing forcing(1e-6, 0.1, 3e-8);
  forcing.first();
  forcing.next(1e-3, 1.0);
  // Quadratic convergence would ask 0.9 (3e-4)^1.5 = 4.7e-6; a linear residual of 0.5 tau = 1.5e-8
  // is all the residual test at 3e-8 needs: 0.5 * 3e-8 / 3e-7 = 0.05.
  EXPECT_NEAR(forcing.next(3e-7, 1e-3), 0.05, 1e-15);
  // Never looser than the ceiling.
  InexactNewtonForcing capped(1e-6, 1e-2, 3e-8);
  capped.first();
  EXPECT_EQ(capped.next(3e-7, 1e-3), 1e-2);
}

TEST(InexactNewtonForcing, StaysAboveTheDeckTolerance) {
  InexactNewtonForcing forcing(1e-6, 1e-2, 0.0);
  forcing.first();
  EXPECT_EQ(forcing.next(1e-9, 1.0), 1e-6);
}

namespace {
// Inexact Newton on f(x) = (x1^2 + x2 - 3, x1 + x2^3 - 9) (root (1, 2)): each linear solve leaves
// exactly the relative residual eta (the step is (1 - eta) times the exact Newton step), the
// worst a Krylov solve to eta may do in the direction of f. Returns the iterations to ||f|| <= tau
// and the last eta; `bounded` false: no over-solving bound (tau = 0 for the forcing).
struct ModelRun {
  int iterations = 0;
  double lastEta = 0.0, residual = 0.0;
};
ModelRun solveModel(double tau, bool bounded) {
  double x1 = 1.6, x2 = 2.5;
  auto residual = [&](double &f1, double &f2) {
    f1 = x1 * x1 + x2 - 3.0;
    f2 = x1 + x2 * x2 * x2 - 9.0;
    return std::hypot(f1, f2);
  };
  InexactNewtonForcing forcing(1e-10, 1e-2, bounded ? tau : 0.0);
  ModelRun run;
  double f1 = 0.0, f2 = 0.0, previous = 0.0;
  double norm = residual(f1, f2);
  while (norm > tau && run.iterations < 50) {
    run.lastEta = run.iterations == 0 ? forcing.first() : forcing.next(norm, previous);
    const double j11 = 2.0 * x1, j12 = 1.0, j21 = 1.0, j22 = 3.0 * x2 * x2, det = j11 * j22 - j12 * j21;
    const double d1 = -(j22 * f1 - j12 * f2) / det, d2 = -(-j21 * f1 + j11 * f2) / det;
    x1 += (1.0 - run.lastEta) * d1;
    x2 += (1.0 - run.lastEta) * d2;
    previous = norm;
    norm = residual(f1, f2);
    ++run.iterations;
  }
  run.residual = norm;
  return run;
}
} // namespace

TEST(InexactNewtonForcing, TheBoundLoosensTheLastSolveWithoutAnotherIteration) {
  const double tau = 1e-8;
  const ModelRun plain = solveModel(tau, false), bounded = solveModel(tau, true);
  EXPECT_LE(plain.residual, tau);
  EXPECT_LE(bounded.residual, tau);
  EXPECT_EQ(bounded.iterations, plain.iterations);
  // The last solve of the plain choice 2 asks far more than tau needs; the bounded one no more
  // than half of tau relative to the residual it starts from.
  EXPECT_GT(bounded.lastEta, 100.0 * plain.lastEta);
}
