// solveBoundedLeastSquares against an independent exact solution: for small n, enumerate every
// assignment of each variable to {lower, upper, free}, solve the free part, keep the feasible
// candidate with the least objective (the box-constrained minimiser of a strictly convex
// quadratic is one of them). Plus the closed form when the box is inactive, KKT on the result,
// a zero column with damping, fixed variables and input validation.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "control/BoundedLeastSquares.hpp"

namespace glossa::control {
namespace {

double objective(const Eigen::MatrixXd &A, const Eigen::VectorXd &b, double rho, const Eigen::VectorXd &x) {
  return (A * x - b).squaredNorm() + rho * x.squaredNorm();
}

Eigen::VectorXd bruteForce(const Eigen::MatrixXd &A, const Eigen::VectorXd &b, const Eigen::VectorXd &lo,
                           const Eigen::VectorXd &hi, double rho) {
  const int n = static_cast<int>(A.cols());
  const Eigen::MatrixXd H = A.transpose() * A + rho * Eigen::MatrixXd::Identity(n, n);
  const Eigen::VectorXd g = A.transpose() * b;
  int combos = 1;
  for (int i = 0; i < n; ++i) combos *= 3;
  Eigen::VectorXd best;
  double bestValue = std::numeric_limits<double>::infinity();
  for (int c = 0; c < combos; ++c) {
    Eigen::VectorXd x(n);
    std::vector<int> free;
    int code = c;
    for (int i = 0; i < n; ++i, code /= 3) {
      if (code % 3 == 0) x(i) = lo(i);
      else if (code % 3 == 1) x(i) = hi(i);
      else free.push_back(i), x(i) = 0.0;
    }
    if (!free.empty()) {
      const int m = static_cast<int>(free.size());
      Eigen::MatrixXd HF(m, m);
      Eigen::VectorXd r(m);
      for (int a = 0; a < m; ++a) {
        r(a) = g(free[a]) - H.row(free[a]).dot(x);
        for (int d = 0; d < m; ++d) HF(a, d) = H(free[a], free[d]);
      }
      const Eigen::VectorXd z = HF.fullPivLu().solve(r);
      for (int a = 0; a < m; ++a) x(free[a]) = z(a);
    }
    if ((x - lo).minCoeff() < -1e-12 || (hi - x).minCoeff() < -1e-12) continue;
    const double v = objective(A, b, rho, x);
    if (v < bestValue) bestValue = v, best = x;
  }
  return best;
}

TEST(BoundedLeastSquares, MatchesEnumerationOfActiveSetsOnRandomProblems) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % 6, m = 3 * (1 + trial % 4);
    Eigen::MatrixXd A(m, n);
    Eigen::VectorXd b(m);
    for (int i = 0; i < m; ++i) {
      b(i) = 2.0 * normal(rng);
      for (int j = 0; j < n; ++j) A(i, j) = normal(rng);
    }
    // The controller's box: du in [-u, 1 - u] for some u in [0, 1].
    Eigen::VectorXd u = (Eigen::VectorXd::Random(n).array() * 0.5 + 0.5).matrix();
    const Eigen::VectorXd lo = -u, hi = Eigen::VectorXd::Ones(n) - u;
    const double rho = trial % 3 == 0 ? 0.0 : 1e-3;
    if (m < n && rho == 0.0) continue; // not unique
    const auto r = solveBoundedLeastSquares(A, b, lo, hi, rho);
    ASSERT_TRUE(r.converged) << "trial " << trial;
    const Eigen::VectorXd expected = bruteForce(A, b, lo, hi, rho);
    EXPECT_NEAR(objective(A, b, rho, r.x), objective(A, b, rho, expected), 1e-10 * (1.0 + b.squaredNorm()))
        << "trial " << trial;
    EXPECT_LT((r.x - expected).cwiseAbs().maxCoeff(), 1e-8) << "trial " << trial;
  }
}

TEST(BoundedLeastSquares, InactiveBoxGivesTheUnconstrainedSolution) {
  Eigen::MatrixXd A(4, 2);
  A << 1, 0, 0, 2, 1, 1, 0.5, -1;
  const Eigen::VectorXd xTrue = Eigen::Vector2d(0.3, -0.2);
  const Eigen::VectorXd b = A * xTrue;
  const auto r = solveBoundedLeastSquares(A, b, Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, 1));
  EXPECT_TRUE(r.converged);
  EXPECT_LT((r.x - xTrue).norm(), 1e-12);
}

TEST(BoundedLeastSquares, ResultSatisfiesKkt) {
  Eigen::MatrixXd A(3, 3);
  A << 1, 0.2, 0, 0, 1, 0.3, 0.1, 0, 1;
  const Eigen::Vector3d b(5.0, -5.0, 0.2);
  const Eigen::Vector3d lo(0, 0, 0), hi(1, 1, 1);
  const auto r = solveBoundedLeastSquares(A, b, lo, hi);
  const Eigen::Vector3d gradient = A.transpose() * (A * r.x - b);
  for (int i = 0; i < 3; ++i) {
    if (r.x(i) <= lo(i) + 1e-14) EXPECT_GE(gradient(i), -1e-12) << i;
    else if (r.x(i) >= hi(i) - 1e-14) EXPECT_LE(gradient(i), 1e-12) << i;
    else EXPECT_NEAR(gradient(i), 0.0, 1e-12) << i;
  }
  EXPECT_DOUBLE_EQ(r.x(0), 1.0);
  EXPECT_DOUBLE_EQ(r.x(1), 0.0);
}

TEST(BoundedLeastSquares, DampingPinsAVariableThatMovesNothing) {
  Eigen::MatrixXd A(3, 2);
  A << 1, 0, 2, 0, 0.5, 0; // the second variable has no effect
  const Eigen::Vector3d b(1, 2, 0.5);
  const auto r = solveBoundedLeastSquares(A, b, Eigen::Vector2d(-1, -0.5), Eigen::Vector2d(2, 0.5), 1e-8);
  EXPECT_NEAR(r.x(0), 1.0, 1e-6);
  EXPECT_EQ(r.x(1), 0.0);
}

TEST(BoundedLeastSquares, EqualBoundsFixTheVariable) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(2, 2);
  const auto r = solveBoundedLeastSquares(A, Eigen::Vector2d(3, 3), Eigen::Vector2d(0.25, -1), Eigen::Vector2d(0.25, 1));
  EXPECT_EQ(r.x(0), 0.25);
  EXPECT_EQ(r.x(1), 1.0);
}

TEST(BoundedLeastSquares, RejectsBadInput) {
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(2, 2);
  EXPECT_THROW(solveBoundedLeastSquares(A, Eigen::Vector3d::Zero(), Eigen::Vector2d::Zero(), Eigen::Vector2d::Ones()),
               std::invalid_argument);
  EXPECT_THROW(solveBoundedLeastSquares(A, Eigen::Vector2d::Zero(), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)),
               std::invalid_argument);
  EXPECT_THROW(solveBoundedLeastSquares(A, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), Eigen::Vector2d::Ones(), -1.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace glossa::control
