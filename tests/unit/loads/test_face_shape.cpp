#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "loads/FaceShape.hpp"

using glossa::loads::crossMatrix;
using glossa::loads::faceShape;

// N_a is 1 at node a and 0 at the others (nodes at s = (-1, 1, 1, -1), t = (-1, -1, 1, 1)), the
// N_a sum to 1 anywhere, and the derivatives match central differences.
TEST(FaceShape, InterpolatesTheNodesAndDifferentiates) {
  const double s[4] = {-1, 1, 1, -1}, t[4] = {-1, -1, 1, 1};
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) EXPECT_DOUBLE_EQ(faceShape(s[b], t[b]).N(a), a == b ? 1.0 : 0.0);
  const double s0 = 0.3, t0 = -0.7, h = 1e-6;
  const auto q = faceShape(s0, t0);
  EXPECT_NEAR(q.N.sum(), 1.0, 1e-15);
  EXPECT_LT((q.dNds - (faceShape(s0 + h, t0).N - faceShape(s0 - h, t0).N) / (2 * h)).norm(), 1e-9);
  EXPECT_LT((q.dNdt - (faceShape(s0, t0 + h).N - faceShape(s0, t0 - h).N) / (2 * h)).norm(), 1e-9);
}

TEST(FaceShape, CrossMatrixIsTheCrossProduct) {
  const Eigen::Vector3d v(1.5, -2, 0.25), w(-0.5, 3, 4);
  EXPECT_TRUE((crossMatrix(v) * w).isApprox(v.cross(w)));
}
