#include <gtest/gtest.h>

#include "loads/DeadTraction.hpp"

#include <array>

#include <Eigen/LU>

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

// The enclosed volume from 1/3 of the integral of x . n over the faces (faceVolumeMoment), on
// hexahedra whose volume is known: affine images of the unit cube (volume |det A|, whatever
// the origin), and a trilinear, non-affine one (a frustum-like block, volume by its own closed
// form). The faces' node order (outward, right-handed) is that of the mesh's hexahedra; reversed,
// as seen from a cavity the body surrounds, the sum is minus the volume.
namespace {
const int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
const double kCube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

double enclosedVolume(const std::array<Eigen::Vector3d, 8> &x, bool reversed) {
  double v = 0.0;
  for (const auto &face : kFaces) {
    glossa::loads::FaceNodes X;
    for (int k = 0; k < 4; ++k) X.row(reversed ? 3 - k : k) = x[face[k]].transpose();
    v += glossa::loads::faceVolumeMoment(X);
  }
  return v;
}
} // namespace

TEST(FaceVolumeMoment, ClosedSurfacesEncloseTheirVolume) {
  Eigen::Matrix3d A;
  A << 1.3, 0.2, -0.1, //
      0.1, 0.8, 0.3,   //
      -0.2, 0.05, 1.1;
  const Eigen::Vector3d shift(2.0, -1.0, 0.5);
  std::array<Eigen::Vector3d, 8> x;
  for (int a = 0; a < 8; ++a) x[a] = A * Eigen::Vector3d(kCube[a][0], kCube[a][1], kCube[a][2]) + shift;
  EXPECT_NEAR(enclosedVolume(x, false), A.determinant(), 1e-14);
  EXPECT_NEAR(enclosedVolume(x, true), -A.determinant(), 1e-14); // a cavity's wall
  // Trilinear: the top face z = 1 shrunk to [0, 0.5] x [0, 0.5]; cross-sections are squares of
  // side 1 - z/2, so V = int_0^1 (1 - z/2)^2 dz = 7/12.
  for (int a = 0; a < 8; ++a) x[a] = Eigen::Vector3d(kCube[a][0], kCube[a][1], kCube[a][2]);
  for (int a = 4; a < 8; ++a) x[a].head<2>() *= 0.5;
  EXPECT_NEAR(enclosedVolume(x, false), 7.0 / 12.0, 1e-14);
}
