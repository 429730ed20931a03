#include <gtest/gtest.h>

#include "loads/DeadTraction.hpp"

using glossa::loads::FaceNodes;

// The forces of a uniform traction sum to traction x area; on a parallelogram each node gets a
// quarter (exact for the bilinear shape functions on an affine face).
TEST(DeadTraction, ResultantEqualsTractionTimesArea) {
  FaceNodes X;
  X << 0, 0, 0, 2, 0, 0, 2.5, 1, 0, 0.5, 1, 0; // parallelogram, area 2
  const Eigen::Vector3d t(1.0, -3.0, 0.5);
  const auto f = glossa::loads::deadTractionForces(X, t);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int a = 0; a < 4; ++a) {
    sum += f.segment<3>(3 * a);
    EXPECT_LT((f.segment<3>(3 * a) - 0.5 * t).norm(), 1e-14);
  }
  EXPECT_LT((sum - 2.0 * t).norm(), 1e-14);
  EXPECT_NEAR(glossa::loads::faceArea(X), 2.0, 1e-14);
  EXPECT_LT((glossa::loads::faceNormal(X) - Eigen::Vector3d::UnitZ()).norm(), 1e-14);
}
