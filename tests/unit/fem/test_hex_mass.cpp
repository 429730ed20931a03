// The hexahedron's mass matrix against independent references: the total mass rho V of a
// parallelepiped (V the triple product of its edges), the tensor product of the 1D linear
// element's mass (h/6)[2 1; 1 2] on the unit cube, the kinetic energy of a rigid rotation
// (1/2) omega^2 rho int (x^2 + y^2) dV, and the lumped matrix's conservation of the consistent
// one's mass and translational kinetic energy.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "fem/HexMass.hpp"

#include "UnitCube.hpp"

namespace glossa::fem {
namespace {

using testing::unitCube;

// The unit cube mapped by an affine map with edges e1, e2, e3 and an offset.
NodeMatrix parallelepiped(const Eigen::Matrix3d &edges, const Eigen::Vector3d &offset) {
  const NodeMatrix unit = unitCube();
  NodeMatrix X;
  for (int a = 0; a < 8; ++a) X.row(a) = (edges * unit.row(a).transpose() + offset).transpose();
  return X;
}

// The nodal velocity vector of a rigid motion v(X) = w + omega x X.
Eigen::Matrix<double, 24, 1> rigidVelocity(const NodeMatrix &X, const Eigen::Vector3d &w, const Eigen::Vector3d &omega) {
  Eigen::Matrix<double, 24, 1> v;
  for (int a = 0; a < 8; ++a) v.segment<3>(3 * a) = w + omega.cross(X.row(a).transpose());
  return v;
}

TEST(HexMass, TotalMassIsDensityTimesVolume) {
  Eigen::Matrix3d edges;
  edges << 0.02, 0.004, -0.003, 0.001, 0.015, 0.002, 0.003, -0.002, 0.03;
  const NodeMatrix X = parallelepiped(edges, Eigen::Vector3d(0.1, -0.2, 0.05));
  const double rho = 1060.0, mass = rho * edges.determinant();
  for (MassLumping lumping : {MassLumping::consistent, MassLumping::lumped}) {
    ElementMass M;
    ASSERT_TRUE(hexMass(X, rho, lumping, M));
    for (int i = 0; i < 3; ++i) {
      // A unit translation along i: u^T M u is the mass.
      Eigen::Matrix<double, 24, 1> t = Eigen::Matrix<double, 24, 1>::Zero();
      for (int a = 0; a < 8; ++a) t(3 * a + i) = 1.0;
      EXPECT_NEAR(t.dot(M * t), mass, 1e-12 * mass);
    }
    EXPECT_NEAR(M.sum(), 3.0 * mass, 3e-12 * mass);
  }
}

TEST(HexMass, UnitCubeIsTheTensorProductOfTheLinearElement) {
  ElementMass M;
  ASSERT_TRUE(hexMass(unitCube(), 2.0, MassLumping::consistent, M));
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      // (1/6)(2 or 1) per direction: 2 where the nodes share the coordinate.
      double expected = 2.0;
      for (int j = 0; j < 3; ++j) expected *= (hexNodeXi(a)(j) == hexNodeXi(b)(j) ? 2.0 : 1.0) / 6.0;
      EXPECT_NEAR(M(3 * a, 3 * b), expected, 1e-15);
      EXPECT_EQ(M(3 * a, 3 * b + 1), 0.0);
    }
  ElementMass L;
  ASSERT_TRUE(hexMass(unitCube(), 2.0, MassLumping::lumped, L));
  for (int l = 0; l < 24; ++l) EXPECT_NEAR(L(l, l), 2.0 / 8.0, 1e-15); // a cube's nodes share equally
  EXPECT_EQ((L - Eigen::Matrix<double, 24, 24>(L.diagonal().asDiagonal())).norm(), 0.0);
}

TEST(HexMass, LumpedAndConsistentTranslationalKineticEnergiesAgree) {
  Eigen::Matrix3d edges;
  edges << 0.05, 0.01, 0.0, -0.01, 0.04, 0.005, 0.0, 0.002, 0.06;
  NodeMatrix X = parallelepiped(edges, Eigen::Vector3d(0.01, 0.02, 0.03));
  X(6, 0) += 0.004; // not affine: the translation's energy still matches, the total mass being exact
  ElementMass C, L;
  ASSERT_TRUE(hexMass(X, 1100.0, MassLumping::consistent, C));
  ASSERT_TRUE(hexMass(X, 1100.0, MassLumping::lumped, L));
  const auto v = rigidVelocity(X, Eigen::Vector3d(0.3, -1.2, 0.7), Eigen::Vector3d::Zero());
  const double consistent = 0.5 * v.dot(C * v);
  EXPECT_GT(consistent, 0.0);
  EXPECT_NEAR(0.5 * v.dot(L * v), consistent, 1e-12 * consistent);
}

TEST(HexMass, ConsistentRotationalKineticEnergyIsExact) {
  // omega about z through the origin, a corner of the unit cube: int (x^2 + y^2) dV = 2/3. A
  // rigid rotation is linear in X, so the trilinear interpolation carries it exactly.
  const double rho = 1000.0, omega = 3.0;
  ElementMass M;
  ASSERT_TRUE(hexMass(unitCube(), rho, MassLumping::consistent, M));
  const auto v = rigidVelocity(unitCube(), Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, omega));
  EXPECT_NEAR(0.5 * v.dot(M * v), 0.5 * omega * omega * rho * 2.0 / 3.0, 1e-9);
  // Lumped, the mass sits at the corners: sum m_a r_a^2 = (rho/8)(0+1+2+1)*2 = rho, not 2 rho/3.
  ElementMass L;
  ASSERT_TRUE(hexMass(unitCube(), rho, MassLumping::lumped, L));
  EXPECT_NEAR(0.5 * v.dot(L * v), 0.5 * omega * omega * rho, 1e-9);
}

TEST(HexMass, DegenerateElementIsRefused) {
  NodeMatrix X = unitCube();
  X.col(2).setZero(); // flat
  ElementMass M;
  EXPECT_FALSE(hexMass(X, 1000.0, MassLumping::consistent, M));
  EXPECT_EQ(M.norm(), 0.0);
}

} // namespace
} // namespace glossa::fem
