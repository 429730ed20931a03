// minCornerJacobian: det F at the corners, the inside-out check after a converged step. An
// element folded through itself (a corner node pushed to the element's centre) keeps det F > 0
// at all eight Gauss points, so only the corners show that it turned over.

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include <Eigen/LU>

#include "fem/HexShape.hpp"

#include "UnitCube.hpp"

namespace glossa::fem {
namespace {

using testing::unitCube;

double minGaussJacobian(const NodeMatrix &X, const NodeMatrix &u) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto &q : gaussHex2()) {
    Eigen::Matrix<double, 8, 3> dNdX;
    double detJ0 = 0.0;
    EXPECT_TRUE(hexGradients(X, q.xi, dNdX, detJ0));
    smallest = std::min(smallest, (Eigen::Matrix3d::Identity() + u.transpose() * dNdX).determinant());
  }
  return smallest;
}

TEST(CornerJacobian, AffineMapsGiveTheirDeterminantEverywhere) {
  const NodeMatrix X = unitCube();
  Eigen::Matrix3d A;
  A << 1.2, 0.3, 0.0, //
      -0.1, 0.9, 0.2, //
      0.0, 0.4, 1.1;
  const NodeMatrix u = X * (A - Eigen::Matrix3d::Identity()).transpose();
  EXPECT_NEAR(minCornerJacobian(X, u), A.determinant(), 1e-14);
  EXPECT_NEAR(minCornerJacobian(X, NodeMatrix::Zero()), 1.0, 1e-15);
}

TEST(CornerJacobian, AnElementFoldedThroughItselfIsSeenAtTheCorners) {
  const NodeMatrix X = unitCube();
  NodeMatrix u = NodeMatrix::Zero();
  u.row(6) = Eigen::RowVector3d(0.5, 0.5, 0.5) - X.row(6); // node (1, 1, 1) to the centre
  // Closed forms for this fold: the Gauss points' smallest det F is (2 - sqrt 3)/4 > 0, the corner
  // at the moved node has det F = -1/2.
  EXPECT_NEAR(minGaussJacobian(X, u), 0.066987298107780, 1e-12);
  EXPECT_NEAR(minCornerJacobian(X, u), -0.5, 1e-14);
}

// A poorly shaped hexahedron (one corner pushed nearly into the plane of its neighbours) has a
// near-degenerate corner where any motion makes a large det F; the regular corners leave it out.
TEST(CornerJacobian, RegularCornersLeaveOutANearlyDegenerateOne) {
  NodeMatrix X = unitCube();
  // Node (1, 1, 1) at (0.7, 0.7, 0.7), near the plane x + y + z = 2 of its three neighbours: its
  // corner's reference det is 0.129 of the mean. Moving it by -0.1 in each direction takes it
  // across that plane: det F = -2 there, 6/7 at the neighbours' corners, 1 at the others.
  X.row(6) = Eigen::RowVector3d(0.7, 0.7, 0.7);
  NodeMatrix u = NodeMatrix::Zero();
  u.row(6) = Eigen::RowVector3d(-0.1, -0.1, -0.1);
  EXPECT_NEAR(minCornerJacobian(X, u), -2.0, 1e-12);
  EXPECT_NEAR(minRegularCornerJacobian(X, u, 0.2), 6.0 / 7.0, 1e-12);
  // Every corner counts at regularity 0; none at a regularity above their largest ratio.
  EXPECT_EQ(minRegularCornerJacobian(X, u, 0.0), minCornerJacobian(X, u));
  EXPECT_EQ(minRegularCornerJacobian(X, u, 10.0), std::numeric_limits<double>::infinity());
}

TEST(CornerJacobian, AFoldAtARegularCornerIsSeenByBoth) {
  const NodeMatrix X = unitCube();
  NodeMatrix u = NodeMatrix::Zero();
  u.row(6) = Eigen::RowVector3d(0.5, 0.5, 0.5) - X.row(6);
  EXPECT_NEAR(minRegularCornerJacobian(X, u, 0.2), -0.5, 1e-14);
}

// A zero-strain configuration can turn a near-degenerate corner of the imaged mesh over (the
// tongue's element 145: det dX/dxi there -0.1 of its element's mean, every Gauss point positive).
// det F at that corner is the ratio of the deformed and reference dets, 1 at rest, not -inf; a
// corner whose reference det is exactly 0 has none and is left out.
TEST(CornerJacobian, ATurnedOverReferenceCornerHasItsRatio) {
  NodeMatrix X = unitCube();
  X.row(6) = Eigen::RowVector3d(0.66, 0.66, 0.66); // across the plane x + y + z = 2 of its neighbours
  EXPECT_NEAR(minCornerJacobian(X, NodeMatrix::Zero()), 1.0, 1e-14);
  NodeMatrix u = NodeMatrix::Zero();
  u.row(6) = Eigen::RowVector3d(0.01, 0.01, 0.01); // back onto the plane's other side: (3 0.67 - 2) / (3 0.66 - 2)
  EXPECT_NEAR(minCornerJacobian(X, u), -0.5, 1e-9);
  X.row(6) = Eigen::RowVector3d(2.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0); // on the plane: det dX/dxi = 0 there
  EXPECT_NEAR(minCornerJacobian(X, NodeMatrix::Zero()), 1.0, 1e-12);
}

} // namespace
} // namespace glossa::fem
