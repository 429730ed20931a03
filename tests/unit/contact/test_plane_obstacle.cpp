#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "ObstacleChecks.hpp"
#include "contact/PlaneObstacle.hpp"

using glossa::contact::PlaneObstacle;

// The plane z = 3 with the body above it: a point half a unit below has gap -0.5 and its closest
// point straight above it; the given normal (0, 0, 2) is made unit.
TEST(PlaneObstacle, GapNormalAndClosestPointByHand) {
  const PlaneObstacle plane(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0, 0, 2));
  const auto cp = plane.closest(Eigen::Vector3d(5, -1, 2.5), 1.0);
  ASSERT_TRUE(cp);
  EXPECT_DOUBLE_EQ(cp->gap, -0.5);
  EXPECT_TRUE(cp->point.isApprox(Eigen::Vector3d(5, -1, 3)));
  EXPECT_TRUE(cp->normal.isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_EQ(cp->dNormal, Eigen::Matrix3d::Zero());
}

// A tilted plane through the origin with normal (1, 1, 0)/sqrt 2: (2, 0, 0) is sqrt 2 above it.
TEST(PlaneObstacle, TiltedPlaneGapIsTheSignedDistance) {
  const PlaneObstacle plane(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 0));
  const auto cp = plane.closest(Eigen::Vector3d(2, 0, 0), 2.0);
  ASSERT_TRUE(cp);
  EXPECT_NEAR(cp->gap, std::sqrt(2.0), 1e-15);
  EXPECT_TRUE(cp->point.isApprox(Eigen::Vector3d(1, -1, 0)));
  glossa::contact::test::expectConsistentClosestPoint(plane, Eigen::Vector3d(0.3, -2, 7), "tilted");
}

// Beyond the search radius, on either side, the plane is not reported.
TEST(PlaneObstacle, NothingBeyondTheSearchRadius) {
  const PlaneObstacle plane(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1));
  EXPECT_FALSE(plane.closest(Eigen::Vector3d(0, 0, 0.3), 0.2));
  EXPECT_FALSE(plane.closest(Eigen::Vector3d(0, 0, -0.3), 0.2));
  EXPECT_TRUE(plane.closest(Eigen::Vector3d(0, 0, -0.3), 0.4));
}

TEST(PlaneObstacle, ZeroNormalIsRefused) {
  EXPECT_THROW(PlaneObstacle(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()), std::invalid_argument);
}
