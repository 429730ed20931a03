#include <gtest/gtest.h>

#include <cmath>

#include "MaterialConformance.hpp"
#include "materials/FungIsotropic.hpp"

using glossa::materials::FungIsotropic;

TEST(FungIsotropic, AdiposeConformance) { glossa::test::expectConformance(FungIsotropic::adipose(), 11u); }
TEST(FungIsotropic, MuscleMatrixConformance) {
  glossa::test::expectConformance(FungIsotropic::muscleMatrix(), 12u);
}

// The paper's parameter values (eq. 9, Table I) and the small-strain shear modulus 2 A B.
TEST(FungIsotropic, ParameterSetsAndShearModulus) {
  EXPECT_EQ(FungIsotropic::adipose().A(), 2500.0);
  EXPECT_EQ(FungIsotropic::adipose().B(), 2.75);
  EXPECT_EQ(FungIsotropic::muscleMatrix().A(), 1652.0);
  EXPECT_EQ(FungIsotropic::muscleMatrix().B(), 0.6265);
  for (const FungIsotropic &m : {FungIsotropic::adipose(), FungIsotropic::muscleMatrix()}) {
    EXPECT_DOUBLE_EQ(m.shearModulus(), 2.0 * m.A() * m.B());
    // Simple shear gamma: P_12 = mu gamma + O(gamma^3).
    const double gamma = 1e-4;
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    F(0, 1) = gamma;
    EXPECT_NEAR(m.evaluate(F).P(0, 1), m.shearModulus() * gamma, 1e-7 * m.shearModulus() * gamma);
  }
  // Small-strain Young's modulus of the muscle matrix, E = 3 mu = 6 c b = 6.21 kPa (doc/materials.md).
  EXPECT_NEAR(3.0 * FungIsotropic::muscleMatrix().shearModulus(), 6 * 1652.0 * 0.6265, 1e-9);
  EXPECT_NEAR(3.0 * FungIsotropic::muscleMatrix().shearModulus(), 6209.868, 1e-3);
}

// Incompressible uniaxial stretch: sigma_11 - sigma_22 = 2 psi'(I1) (lambda^2 - 1/lambda),
// psi' = A B exp(B (I1 - 3)), I1 = lambda^2 + 2/lambda.
TEST(FungIsotropic, UniaxialIncompressibleStressDifference) {
  const FungIsotropic m = FungIsotropic::muscleMatrix();
  for (double lambda : {0.6, 0.9, 1.3, 2.0}) {
    Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
    F(0, 0) = lambda;
    F(1, 1) = F(2, 2) = 1.0 / std::sqrt(lambda);
    const Eigen::Matrix3d sigma = m.evaluate(F).P * F.transpose();
    const double I1 = lambda * lambda + 2.0 / lambda;
    const double expected =
        2.0 * m.A() * m.B() * std::exp(m.B() * (I1 - 3.0)) * (lambda * lambda - 1.0 / lambda);
    EXPECT_NEAR(sigma(0, 0) - sigma(1, 1), expected, 1e-10 * std::abs(expected));
    EXPECT_NEAR(sigma.trace(), 0.0, 1e-9 * m.A());  // the isochoric stress is deviatoric
  }
}

TEST(FungIsotropic, RejectsInvalidParameters) {
  EXPECT_THROW(FungIsotropic(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(FungIsotropic(1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(FungIsotropic(NAN, 1.0), std::invalid_argument);
}
