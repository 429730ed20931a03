#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "ObstacleChecks.hpp"
#include "contact/SphereObstacle.hpp"

using glossa::contact::BodySide;
using glossa::contact::SphereObstacle;

// Centre (1, 0, 0), radius 2: the point c + (3, 4, 0) is 5 from the centre, so 3 outside the
// sphere along (0.6, 0.8, 0), its closest point c + 2 (0.6, 0.8, 0); dNormal = (I - n n)/5.
TEST(SphereObstacle, BodyOutsideByHand) {
  const Eigen::Vector3d c(1, 0, 0);
  const SphereObstacle sphere(c, 2.0);
  const auto cp = sphere.closest(c + Eigen::Vector3d(3, 4, 0), 10.0);
  ASSERT_TRUE(cp);
  const Eigen::Vector3d n(0.6, 0.8, 0);
  EXPECT_DOUBLE_EQ(cp->gap, 3.0);
  EXPECT_TRUE(cp->normal.isApprox(n));
  EXPECT_TRUE(cp->point.isApprox(c + 2 * n));
  EXPECT_TRUE(cp->dNormal.isApprox((Eigen::Matrix3d::Identity() - n * n.transpose()) / 5));
  // Half a unit inside the sphere: gap -0.5.
  EXPECT_DOUBLE_EQ(sphere.closest(c + Eigen::Vector3d(0, 0, 1.5), 1.0)->gap, -0.5);
}

// The same sphere as a cavity: a point 1.5 from the centre is 0.5 clear of the wall, the normal
// points back to the centre, and a point 5 from the centre has gone 3 through the wall.
TEST(SphereObstacle, BodyInsideACavityByHand) {
  const Eigen::Vector3d c(1, 0, 0);
  const SphereObstacle cavity(c, 2.0, BodySide::inside);
  const auto cp = cavity.closest(c + Eigen::Vector3d(0, 0, 1.5), 1.0);
  ASSERT_TRUE(cp);
  EXPECT_DOUBLE_EQ(cp->gap, 0.5);
  EXPECT_TRUE(cp->normal.isApprox(Eigen::Vector3d(0, 0, -1)));
  EXPECT_TRUE(cp->point.isApprox(c + Eigen::Vector3d(0, 0, 2)));
  EXPECT_DOUBLE_EQ(cavity.closest(c + Eigen::Vector3d(3, 4, 0), 10.0)->gap, -3.0);
}

// dNormal against central differences of the normal at random points, either side of the wall,
// for both sides of the body.
TEST(SphereObstacle, NormalDerivativeMatchesCentralDifferences) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(-2.5, 2.5);
  const SphereObstacle outside(Eigen::Vector3d(0.2, -0.1, 0.4), 1.3);
  const SphereObstacle inside(Eigen::Vector3d(0.2, -0.1, 0.4), 1.3, BodySide::inside);
  for (int sample = 0; sample < 20; ++sample) {
    const Eigen::Vector3d x(d(rng), d(rng), d(rng));
    glossa::contact::test::expectConsistentClosestPoint(outside, x, "outside " + std::to_string(sample));
    glossa::contact::test::expectConsistentClosestPoint(inside, x, "inside " + std::to_string(sample));
  }
}

// At the centre no direction is the normal: nothing is reported; beyond the search radius either.
TEST(SphereObstacle, NothingAtTheCentreOrBeyondTheSearchRadius) {
  const SphereObstacle sphere(Eigen::Vector3d::Zero(), 1.0);
  EXPECT_FALSE(sphere.closest(Eigen::Vector3d::Zero(), 10.0));
  EXPECT_FALSE(sphere.closest(Eigen::Vector3d(0, 1.5, 0), 0.4));
  EXPECT_TRUE(sphere.closest(Eigen::Vector3d(0, 1.5, 0), 0.6));
  EXPECT_THROW(SphereObstacle(Eigen::Vector3d::Zero(), 0.0), std::invalid_argument);
}
