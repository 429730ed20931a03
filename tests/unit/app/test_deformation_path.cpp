// glossa point's F(t) for each path, against what defines the path: uniaxial stretch lambda
// along e with lateral contraction 1/sqrt(lambda) (det F = 1), simple shear F = 1 + gamma e m^T,
// a table linear between its rows and constant beyond them.
#include <cmath>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "app/DeformationPath.hpp"

namespace glossa::app {
namespace {

using input::PointParameters;
using input::PointPath;

TEST(DeformationPath, UniaxialStretchesAlongTheDirectionAtConstantVolume) {
  PointParameters p;
  p.direction = Eigen::Vector3d(1, 1, 0).normalized();
  p.amplitude = 0.5;
  p.scale = model::TimeFunction::ramp(2.0);
  const double lambda = 1.25; // 1 + 0.5 * (1 s / 2 s)
  EXPECT_DOUBLE_EQ(pathParameter(p, 1.0), 0.25);
  const Eigen::Matrix3d F = deformationGradient(p, 1.0);
  const Eigen::Vector3d across = Eigen::Vector3d(1, -1, 0).normalized();
  EXPECT_NEAR((F * p.direction - lambda * p.direction).norm(), 0.0, 1e-15);
  EXPECT_NEAR((F * across - across / std::sqrt(lambda)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((F * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ() / std::sqrt(lambda)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(F.determinant(), 1.0, 1e-14);
  EXPECT_NEAR((deformationGradient(p, 0.0) - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-15);
}

TEST(DeformationPath, SimpleShearMovesPlanesAlongTheDirection) {
  PointParameters p;
  p.path = PointPath::simpleShear;
  p.direction = Eigen::Vector3d::UnitZ();
  p.shearPlaneNormal = Eigen::Vector3d::UnitX();
  p.amplitude = 0.4;
  const Eigen::Matrix3d F = deformationGradient(p, 0.7);
  Eigen::Matrix3d expected = Eigen::Matrix3d::Identity();
  expected(2, 0) = 0.4; // x -> x + gamma X e_z
  EXPECT_EQ(F, expected);
  EXPECT_EQ(pathParameter(p, 0.7), 0.4);
  EXPECT_DOUBLE_EQ(F.determinant(), 1.0);
}

TEST(DeformationPath, ATableIsLinearBetweenRowsAndConstantBeyond) {
  PointParameters p;
  p.path = PointPath::table;
  p.amplitude = 0.3; // a table has no path parameter: its rows are F itself
  Eigen::Matrix3d stretched = Eigen::Matrix3d::Identity();
  stretched(0, 0) = 1.2;
  stretched(0, 1) = 0.1;
  p.times = {1.0, 2.0};
  p.table = {Eigen::Matrix3d::Identity(), stretched};
  EXPECT_EQ(deformationGradient(p, 0.5), Eigen::Matrix3d::Identity());
  EXPECT_NEAR((deformationGradient(p, 1.25) - (0.75 * Eigen::Matrix3d::Identity() + 0.25 * stretched)).norm(), 0.0,
              1e-15);
  EXPECT_EQ(deformationGradient(p, 2.0), stretched);
  EXPECT_EQ(deformationGradient(p, 5.0), stretched);
  EXPECT_EQ(pathParameter(p, 1.5), 0.0);
}

} // namespace
} // namespace glossa::app
