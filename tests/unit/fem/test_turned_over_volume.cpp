// turnedOverVolume / turnedOverFraction / folded: the fold check after a converged step. Each
// value is checked against a brute-force integral of max(0, -det dx/dxi) on a fine grid of
// sub-cube midpoints, an independent quadrature, or against an exact volume; slivers to 1e-5 of
// the element's volume (the threshold is 2.5e-3).

#include <gtest/gtest.h>

#include <algorithm>

#include <Eigen/LU>

#include "fem/TurnedOverVolume.hpp"

#include "UnitCube.hpp"

namespace glossa::fem {
namespace {

using testing::unitCube;

// The midpoint rule on n^3 sub-cubes of [-1, 1]^3.
double bruteForceTurnedOver(const NodeMatrix &x, int n = 64) {
  const double h = 2.0 / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Eigen::Vector3d xi(-1.0 + (i + 0.5) * h, -1.0 + (j + 0.5) * h, -1.0 + (k + 0.5) * h);
        sum += std::max(0.0, -(x.transpose() * hexShapeGradient(xi)).determinant());
      }
  return sum * h * h * h;
}

// det dX/dxi at corner a over the mean of the eight.
double referenceCornerRatio(const NodeMatrix &X, int a) {
  double mean = 0.0;
  for (int b = 0; b < 8; ++b) mean += (X.transpose() * hexShapeGradient(hexNodeXi(b))).determinant() / 8.0;
  return (X.transpose() * hexShapeGradient(hexNodeXi(a))).determinant() / mean;
}

// The unit cube with node (1, 1, 1) at (s, s, s): near the plane x + y + z = 2 of its three
// neighbours its corner is poor, as the tongue's imaged mesh has them (0.03 of the mean).
NodeMatrix poorCube(double s) {
  NodeMatrix X = unitCube();
  X.row(6) = Eigen::RowVector3d(s, s, s);
  return X;
}

TEST(TurnedOverVolume, NoneInASoundElementAllInAMirroredOne) {
  const NodeMatrix X = unitCube();
  EXPECT_EQ(turnedOverFraction(X, NodeMatrix::Zero()), 0.0);
  Eigen::Matrix3d A;
  A << 1.2, 0.3, 0.0, //
      -0.1, 0.9, 0.2, //
      0.0, 0.4, 1.1;
  EXPECT_EQ(turnedOverFraction(X, X * (A - Eigen::Matrix3d::Identity()).transpose()), 0.0);
  // A reflection turns the whole element over: V- = |det A| V.
  const Eigen::Matrix3d mirror = Eigen::Vector3d(-1.0, 1.0, 1.0).asDiagonal() * A;
  EXPECT_NEAR(turnedOverVolume(X * mirror.transpose()), std::abs(mirror.determinant()), 1e-14);
  EXPECT_NEAR(turnedOverFraction(X, X * (mirror - Eigen::Matrix3d::Identity()).transpose()), A.determinant(), 1e-14);
  EXPECT_NEAR(hexVolume(X), 1.0, 1e-15);
}

// The textbook fold: a corner node of a regular cube pushed to its centre. Every Gauss point
// keeps det F > 0 (tests/unit/fem/test_corner_jacobian.cpp), a sliver of the cube is turned over,
// and the rule refuses it.
TEST(TurnedOverVolume, ARegularCubeFoldedThroughItselfIsFolded) {
  const NodeMatrix X = unitCube();
  NodeMatrix u = NodeMatrix::Zero();
  u.row(6) = Eigen::RowVector3d(0.5, 0.5, 0.5) - X.row(6);
  const double reference = bruteForceTurnedOver(X + u, 128);
  EXPECT_NEAR(turnedOverFraction(X, u) / reference, 1.0, 5e-3); // 0.3076 % of the cube
  EXPECT_NEAR(minCornerJacobian(X, u), -0.5, 1e-14);
  EXPECT_TRUE(folded(X, u));
  // Half-way to the centre the corner is still sound: nothing turned over.
  u.row(6) *= 0.5;
  EXPECT_EQ(turnedOverFraction(X, u), 0.0);
  EXPECT_FALSE(folded(X, u));
}

// A poor corner, 0.033 of its element's mean, moved 0.08 of the element's size across the plane
// of its neighbours: det F = -8.6 there, far below the fold's -0.5, yet only 0.024 % of the
// element is turned over. A corner threshold refuses it; the volume does not.
TEST(TurnedOverVolume, APoorCornerTurnedOverIsNotAFold) {
  const NodeMatrix X = poorCube(0.675);
  ASSERT_NEAR(referenceCornerRatio(X, 6), 0.0331, 1e-4);
  NodeMatrix u = NodeMatrix::Zero();
  u.row(6) = Eigen::RowVector3d(-0.08, -0.08, -0.08);
  EXPECT_NEAR(minCornerJacobian(X, u), -8.6, 1e-9); // (3 (0.675 - 0.08) - 2) / (3 0.675 - 2)
  const double fraction = turnedOverFraction(X, u);
  EXPECT_NEAR(fraction, bruteForceTurnedOver(X + u, 128) / hexVolume(X), 1e-5); // 2.4e-4 of the volume
  EXPECT_LT(fraction, 0.1 * kFoldedFraction);
  EXPECT_FALSE(folded(X, u));
}

// A zero-strain configuration may hold a corner already turned over (its node across the plane of
// its neighbours, the Gauss points positive). The element is judged against that reference: at
// rest nothing is turned over, and only what a deformation adds counts.
TEST(TurnedOverVolume, AReferenceWithATurnedOverCornerIsJudgedAgainstItself) {
  const NodeMatrix X = poorCube(0.66);
  ASSERT_LT(referenceCornerRatio(X, 6), 0.0);
  const double already = turnedOverVolume(X);
  EXPECT_GT(already, 0.0);
  EXPECT_NEAR(already, bruteForceTurnedOver(X, 128), 1e-5); // a sliver: 2.7e-9 of the volume converged
  EXPECT_EQ(turnedOverFraction(X, NodeMatrix::Zero()), 0.0);
  // Pushing the node to the cube's centre folds it as it folds the regular cube.
  NodeMatrix u = NodeMatrix::Zero();
  u.row(6) = Eigen::RowVector3d(0.5, 0.5, 0.5) - X.row(6);
  EXPECT_NEAR(turnedOverFraction(X, u), (bruteForceTurnedOver(X + u, 128) - already) / hexVolume(X), 2e-5);
  EXPECT_TRUE(folded(X, u));
}

} // namespace
} // namespace glossa::fem
