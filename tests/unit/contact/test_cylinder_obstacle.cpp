#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "ObstacleChecks.hpp"
#include "contact/CylinderObstacle.hpp"

using glossa::contact::BodySide;
using glossa::contact::CylinderObstacle;

// The unit cylinder about the vertical line through (0, 0, 1): (3, 4, 7) is 5 from the axis, so
// 4 outside along (0.6, 0.8, 0), its closest point (0.6, 0.8, 7) at the same height; inside (a
// tube), the same point has gone 4 through the wall and the normal points to the axis.
TEST(CylinderObstacle, GapNormalAndClosestPointByHand) {
  const CylinderObstacle outside(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, 3), 1.0);
  const Eigen::Vector3d x(3, 4, 7), n(0.6, 0.8, 0);
  const auto cp = outside.closest(x, 10.0);
  ASSERT_TRUE(cp);
  EXPECT_DOUBLE_EQ(cp->gap, 4.0);
  EXPECT_TRUE(cp->normal.isApprox(n));
  EXPECT_TRUE(cp->point.isApprox(Eigen::Vector3d(0.6, 0.8, 7)));
  // The normal turns about the axis only: dNormal = (I - e e - n n)/r.
  const Eigen::Vector3d e(0, 0, 1);
  EXPECT_TRUE(cp->dNormal.isApprox((Eigen::Matrix3d::Identity() - e * e.transpose() - n * n.transpose()) / 5));

  const CylinderObstacle tube(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, 3), 1.0, BodySide::inside);
  const auto in = tube.closest(x, 10.0);
  ASSERT_TRUE(in);
  EXPECT_DOUBLE_EQ(in->gap, -4.0);
  EXPECT_TRUE(in->normal.isApprox(-n));
}

// An oblique axis (1, 1, 0) through the origin: (1, 1, 2) is 2 from it straight up, so 1
// outside a cylinder of radius 1 with the normal (0, 0, 1).
TEST(CylinderObstacle, ObliqueAxisByHand) {
  const CylinderObstacle cylinder(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 0), 1.0);
  const auto cp = cylinder.closest(Eigen::Vector3d(1, 1, 2), 5.0);
  ASSERT_TRUE(cp);
  EXPECT_NEAR(cp->gap, 1.0, 1e-15);
  EXPECT_TRUE(cp->normal.isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(cp->point.isApprox(Eigen::Vector3d(1, 1, 1)));
}

// dNormal against central differences at random points about an oblique axis, both sides.
TEST(CylinderObstacle, NormalDerivativeMatchesCentralDifferences) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-2.5, 2.5);
  const Eigen::Vector3d a(0.3, -0.2, 0.1), e(0.4, -1.0, 0.7);
  const CylinderObstacle outside(a, e, 0.8), inside(a, e, 0.8, BodySide::inside);
  for (int sample = 0; sample < 20; ++sample) {
    const Eigen::Vector3d x(d(rng), d(rng), d(rng));
    glossa::contact::test::expectConsistentClosestPoint(outside, x, "outside " + std::to_string(sample));
    glossa::contact::test::expectConsistentClosestPoint(inside, x, "inside " + std::to_string(sample));
  }
}

TEST(CylinderObstacle, NothingOnTheAxisOrBeyondTheSearchRadius) {
  const CylinderObstacle cylinder(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1), 1.0);
  EXPECT_FALSE(cylinder.closest(Eigen::Vector3d(0, 0, 5), 10.0));
  EXPECT_FALSE(cylinder.closest(Eigen::Vector3d(2, 0, 0), 0.9));
  EXPECT_THROW(CylinderObstacle(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 1.0), std::invalid_argument);
  EXPECT_THROW(CylinderObstacle(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1), -1.0), std::invalid_argument);
}
