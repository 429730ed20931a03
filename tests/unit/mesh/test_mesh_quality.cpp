// elementVolume, meshVolume and the scaled Jacobian against hand-computed elements.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

#include "mesh/BoxGenerator.hpp"
#include "mesh/HexMesh.hpp"
#include "mesh/MeshQuality.hpp"

namespace glossa::mesh {
namespace {

// The unit cube [0,1]^3 in VTK node order.
Eigen::Matrix<double, 8, 3> unitCube() {
  Eigen::Matrix<double, 8, 3> X;
  X << 0, 0, 0,  //
      1, 0, 0,   //
      1, 1, 0,   //
      0, 1, 0,   //
      0, 0, 1,   //
      1, 0, 1,   //
      1, 1, 1,   //
      0, 1, 1;
  return X;
}

// The image of the unit cube under an affine map x -> A x + b.
Eigen::Matrix<double, 8, 3> affineImage(const Eigen::Matrix3d &A, const Eigen::Vector3d &b) {
  return (unitCube() * A.transpose()).rowwise() + b.transpose();
}

TEST(MeshQuality, UnitCube) {
  EXPECT_NEAR(elementVolume(unitCube()), 1.0, 1e-15);
  EXPECT_NEAR(scaledJacobian(unitCube()), 1.0, 1e-15);
}

TEST(MeshQuality, ParallelepipedVolumeIsDeterminant) {
  Eigen::Matrix3d A;
  A << 2.0, 0.3, -0.1,  //
      0.2, 1.5, 0.4,    //
      0.0, -0.3, 0.7;
  EXPECT_NEAR(elementVolume(affineImage(A, Eigen::Vector3d(5, -2, 1))), A.determinant(), 1e-13);
}

TEST(MeshQuality, ShearedElementScaledJacobianIsCosineOfShear) {
  // Edges e1 = (1,0,0), e2 = (s,1,0), e3 = (0,0,1) at every corner (up to sign pairs), so
  // det / (|e1||e2||e3|) = 1 / sqrt(1 + s^2) everywhere, centre included.
  const double s = 0.75;
  Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
  A(0, 1) = s;
  EXPECT_NEAR(scaledJacobian(affineImage(A, Eigen::Vector3d::Zero())), 1.0 / std::sqrt(1 + s * s),
              1e-14);
  // Scaling does not change the scaled Jacobian of a box.
  const Eigen::Matrix3d D = Eigen::Vector3d(3.0, 0.01, 7.0).asDiagonal();
  EXPECT_NEAR(scaledJacobian(affineImage(D, Eigen::Vector3d::Ones())), 1.0, 1e-14);
}

TEST(MeshQuality, WarpedElementVolumeIsExact) {
  // Lift node 6 to z = 1 + d: the map is x = X, y = Y, z = Z (1 + d X Y), det J = 1 + d X Y,
  // so V = \int_0^1 \int_0^1 (1 + d X Y) dX dY = 1 + d / 4, which 2x2x2 Gauss integrates exactly.
  const double d = 0.6;
  Eigen::Matrix<double, 8, 3> X = unitCube();
  X(6, 2) += d;
  EXPECT_NEAR(elementVolume(X), 1.0 + d / 4.0, 1e-14);
  // The edges into node 6 tilt, so the element is valid but no longer a perfect box.
  const double q = scaledJacobian(X);
  EXPECT_GT(q, 0.0);
  EXPECT_LT(q, 1.0);
}

TEST(MeshQuality, InvertedElementIsNegative) {
  // Swapping the bottom and top faces mirrors the element: every corner determinant flips.
  Eigen::Matrix<double, 8, 3> X = unitCube();
  X.topRows<4>().swap(X.bottomRows<4>());
  EXPECT_NEAR(scaledJacobian(X), -1.0, 1e-15);
  EXPECT_NEAR(elementVolume(X), -1.0, 1e-15);
}

TEST(MeshQuality, CollapsedEdgeCountsAsZero) {
  Eigen::Matrix<double, 8, 3> X = unitCube();
  X.row(1) = X.row(0);  // edge 0-1 of length zero
  EXPECT_LE(scaledJacobian(X), 0.0);
}

TEST(MeshQuality, MeshRangeAndVolume) {
  HexMesh mesh = generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1), {2, 1, 1});
  EXPECT_NEAR(meshVolume(mesh), 2.0, 1e-14);
  // Shear only the far node column of element 1 (nodes at x = 2): x -> x + 0.5 y. Element 0
  // stays a unit cube (q = 1); element 1 has a trapezoidal cross-section.
  for (Eigen::Vector3d &x : mesh.nodes) {
    if (x.x() == 2.0) x.x() += 0.5 * x.y();
  }
  const auto [lo, hi] = scaledJacobianRange(mesh);
  EXPECT_NEAR(hi, 1.0, 1e-15);
  // Corner at (2,0,*) of element 1: edges (-1,0,0), (0.5,1,0), (0,0,+-1): q = 1/sqrt(1.25).
  EXPECT_NEAR(lo, 1.0 / std::sqrt(1.25), 1e-14);
  // Volume: the cross-section of element 1 is a trapezoid with parallel sides 1 and 1.5.
  EXPECT_NEAR(meshVolume(mesh), 1.0 + 1.25, 1e-14);
  EXPECT_THROW(scaledJacobianRange(HexMesh{}), std::runtime_error);
}

}  // namespace
}  // namespace glossa::mesh

namespace glossa::mesh {
namespace {

TEST(MeshQuality, MinGaussPointJacobian) {
  // The unit cube maps [-1,1]^3 with dX/dxi = I/2: det = 1/8 at every point.
  Eigen::Matrix<double, 8, 3> X;
  X << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1;
  EXPECT_NEAR(minGaussPointJacobian(X), 0.125, 1e-15);
  // Mirrored (top and bottom faces swapped): det = -1/8.
  Eigen::Matrix<double, 8, 3> Y;
  Y << X.bottomRows<4>(), X.topRows<4>();
  EXPECT_NEAR(minGaussPointJacobian(Y), -0.125, 1e-15);
  // Node 6 moved by d = -(1/2, 1/2, 1/2): dX/dxi = I/2 + d (grad N_6)^T, whose determinant is
  // (1/8)(1 + 2 d . grad N_6). grad N_6 = (1/8)(1+eta)(1+zeta), ... is largest at the Gauss point
  // (g, g, g), g = 1/sqrt(3), where each component is (1+g)^2/8: det = (1/8)(1 - 3(1+g)^2/8).
  Eigen::Matrix<double, 8, 3> Z = X;
  Z.row(6) << 0.5, 0.5, 0.5;
  const double g = 1.0 / std::sqrt(3.0);
  EXPECT_NEAR(minGaussPointJacobian(Z), 0.125 * (1 - 3 * (1 + g) * (1 + g) / 8), 1e-15);
}

}  // namespace
}  // namespace glossa::mesh
