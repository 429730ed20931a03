// closestOnTriangle against a dense sampling of the triangle (the point is no farther than
// any sample) and the geometry of each feature: on the interior x - p is normal to the plane,
// on an edge it is normal to the edge, at a corner p is the corner.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "contact/PointTriangle.hpp"

namespace {

using glossa::contact::closestOnTriangle;
using Feature = glossa::contact::TriangleProjection::Feature;

TEST(PointTriangle, ClosestPointIsNoFartherThanAnySampleAndItsFeatureIsRight) {
  const Eigen::Vector3d a(0.1, -0.2, 0.3), b(1.3, 0.1, 0.2), c(0.4, 0.9, -0.1);
  const Eigen::Vector3d corners[3] = {a, b, c};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 2.0);
  int seen[3] = {0, 0, 0};
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Vector3d x(u(rng), u(rng), u(rng));
    const auto pr = closestOnTriangle(x, a, b, c);
    const double d = (x - pr.point).norm();
    const int n = 60;
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const Eigen::Vector3d s = a + (b - a) * i / double(n) + (c - a) * j / double(n);
        ASSERT_LE(d, (x - s).norm() + 1e-14);
      }
    }
    ++seen[static_cast<int>(pr.feature)];
    const Eigen::Vector3d r = x - pr.point;
    switch (pr.feature) {
      case Feature::Face:
        EXPECT_NEAR(r.dot(b - a), 0, 1e-12);
        EXPECT_NEAR(r.dot(c - a), 0, 1e-12);
        break;
      case Feature::Edge: {
        const Eigen::Vector3d p0 = corners[pr.index], p1 = corners[(pr.index + 1) % 3];
        EXPECT_NEAR((pr.point - p0).cross(p1 - p0).norm(), 0, 1e-12);
        EXPECT_NEAR(r.dot(p1 - p0), 0, 1e-12);
        break;
      }
      case Feature::Vertex:
        EXPECT_EQ(pr.point, corners[pr.index]);
        break;
    }
  }
  // The random points reach every kind of region.
  EXPECT_GT(seen[0], 10);
  EXPECT_GT(seen[1], 10);
  EXPECT_GT(seen[2], 10);
}

}  // namespace
