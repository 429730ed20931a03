#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "MaterialConformance.hpp"
#include "materials/FibreReinforcedMaterial.hpp"
#include "materials/FungIsotropic.hpp"
#include "materials/ParallelElement.hpp"

using namespace glossa::materials;

namespace {

std::shared_ptr<const IsochoricMaterial> matrix() {
  return std::make_shared<FungIsotropic>(FungIsotropic::muscleMatrix());
}
std::shared_ptr<const FibreLaw> parallel() {
  return std::make_shared<ParallelElement>(ParallelElement::tableI());
}

// Three families (two oblique) so random deformations stretch some and compress others.
std::vector<FibreFamily> families() {
  return equalFractionFamilies(
      {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 1), Eigen::Vector3d(1, -2, 0.5)});
}

// Tolerances are relative to the stress scale of the fibre law, its stiffness at lambda = 1+.
double fibreScale() { return ParallelElement::tableI().initialStiffness(); }

}  // namespace

TEST(ParallelElement, TensionIsTheDerivativeOfItsEnergy) {
  const ParallelElement p = ParallelElement::tableI();
  EXPECT_NEAR(p.initialStiffness(), 2 * 668.8e3 * 12.43 * 8.568e-4, 1e-9);
  for (double lambda : {1.001, 1.1, 1.3, 1.6}) {
    const double h = 1e-6;
    const FibreTension t = p.evaluate(lambda);
    EXPECT_NEAR(t.T, (p.evaluate(lambda + h).energy - p.evaluate(lambda - h).energy) / (2 * h), 1e-6 * t.T);
    EXPECT_NEAR(t.dTdLambda, (p.evaluate(lambda + h).T - p.evaluate(lambda - h).T) / (2 * h),
                1e-6 * t.dTdLambda);
    // eq. 17 by hand: T0max 2 a A (lambda - 1) exp(a (lambda - 1)^2)
    EXPECT_NEAR(t.T,
                668.8e3 * 2 * 12.43 * 8.568e-4 * (lambda - 1) * std::exp(12.43 * (lambda - 1) * (lambda - 1)),
                1e-12 * 668.8e3);
  }
  for (double lambda : {0.5, 0.9, 1.0}) {
    const FibreTension t = p.evaluate(lambda);
    EXPECT_EQ(t.T, 0.0);
    EXPECT_EQ(t.energy, 0.0);
    EXPECT_EQ(t.dTdLambda, 0.0);
  }
}

TEST(FibreFamily, EqualSplitOfTheTotalFraction) {
  const auto f = families();
  ASSERT_EQ(f.size(), 3u);
  for (const auto &family : f) {
    EXPECT_NEAR(family.volumeFraction, 0.7 / 3.0, 1e-15);
    EXPECT_NEAR(family.N.norm(), 1.0, 1e-15);
  }
  EXPECT_NEAR(validateFibreFamilies(f), 0.3, 1e-15);
  EXPECT_NEAR(validateFibreFamilies(equalFractionFamilies({Eigen::Vector3d::UnitX()}, 0.5)), 0.5, 1e-15);
  EXPECT_THROW(validateFibreFamilies({{Eigen::Vector3d(1, 1, 0), 0.2}}), std::invalid_argument);
  EXPECT_THROW(validateFibreFamilies({{Eigen::Vector3d::UnitX(), 0.6}, {Eigen::Vector3d::UnitY(), 0.6}}),
               std::invalid_argument);
  EXPECT_THROW(equalFractionFamilies({Eigen::Vector3d::Zero()}), std::invalid_argument);
  EXPECT_THROW(equalFractionFamilies({Eigen::Vector3d::UnitX()}, 1.5), std::invalid_argument);
}

TEST(FibreReinforcedMaterial, ConformanceMatrixInFull) {
  glossa::test::expectConformanceAtScale(FibreReinforcedMaterial(matrix(), families(), parallel()), 21u,
                                         fibreScale());
}

TEST(FibreReinforcedMaterial, ConformanceMixtureWeighted) {
  glossa::test::expectConformanceAtScale(
      FibreReinforcedMaterial(matrix(), families(), parallel(), MatrixStressForm::MixtureWeighted), 22u,
      fibreScale());
}

TEST(FibreReinforcedMaterial, ConformanceFibreDirectionRemoved) {
  glossa::test::expectTangentConformance(
      FibreReinforcedMaterial(matrix(), families(), parallel(), MatrixStressForm::FibreDirectionRemoved), 23u,
      fibreScale());
}

// Eq. 5 is eq. 6 minus sum_f phi_f dev[(tau_M : n (x) n) n (x) n], n = F-bar N / lambda-bar.
TEST(FibreReinforcedMaterial, FibreDirectionRemovedSubtractsTheMatrixFibreStress) {
  const auto fam = families();
  const FibreReinforcedMaterial eq6(matrix(), fam, parallel()),
      eq5(matrix(), fam, parallel(), MatrixStressForm::FibreDirectionRemoved);
  std::mt19937 rng(5);
  for (int sample = 0; sample < 10; ++sample) {
    const Eigen::Matrix3d F = glossa::test::randomDeformationGradient(rng, 0.3);
    const double J = F.determinant();
    const Eigen::Matrix3d tauM = matrix()->evaluate(F).P * F.transpose();
    Eigen::Matrix3d expected = eq6.evaluate(F).P * F.transpose();
    for (const auto &f : fam) {
      const Eigen::Vector3d n = (std::pow(J, -1.0 / 3.0) * F * f.N).normalized();
      const Eigen::Matrix3d nn = n * n.transpose();
      const double s = (tauM.array() * nn.array()).sum();
      expected -= f.volumeFraction * s * (nn - Eigen::Matrix3d::Identity() / 3.0);
    }
    EXPECT_LT((eq5.evaluate(F).P * F.transpose() - expected).norm(), 1e-10 * fibreScale());
  }
}

// Fibres resist tension only: compressed fibres add nothing to the matrix response (eq. 6).
TEST(FibreReinforcedMaterial, CompressedFibresCarryNoStress) {
  const FibreReinforcedMaterial m(matrix(), equalFractionFamilies({Eigen::Vector3d::UnitX()}), parallel());
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(0, 0) = 0.8;
  F(1, 1) = F(2, 2) = 1.0 / std::sqrt(0.8);
  F(1, 2) = 0.1;
  const PointResponse r = m.evaluate(F), rM = matrix()->evaluate(F);
  EXPECT_EQ((r.P - rM.P).norm(), 0.0);
  EXPECT_EQ((r.dPdF - rM.dPdF).norm(), 0.0);
  EXPECT_EQ(r.energy, rM.energy);
}

// The tension-only rule belongs to the composite, whatever the fibre law: a law that would also
// resist compression adds nothing while lambda-bar_f <= 1.
TEST(FibreReinforcedMaterial, TensionOnlyForAnyFibreLaw) {
  struct LinearFibre final : FibreLaw {
    FibreTension evaluate(double lambda) const override {
      return {0.5 * 1e4 * (lambda - 1) * (lambda - 1), 1e4 * (lambda - 1), 1e4};
    }
  };
  const FibreReinforcedMaterial m(matrix(), equalFractionFamilies({Eigen::Vector3d::UnitX()}),
                                  std::make_shared<LinearFibre>());
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(0, 0) = 0.9;
  F(1, 1) = F(2, 2) = 1.0 / std::sqrt(0.9);
  EXPECT_EQ((m.evaluate(F).P - matrix()->evaluate(F).P).norm(), 0.0);
  F(0, 0) = 1.1;
  F(1, 1) = F(2, 2) = 1.0 / std::sqrt(1.1);
  EXPECT_GT((m.evaluate(F).P - matrix()->evaluate(F).P).norm(), 100.0);
}

// Incompressible uniaxial stretch along one family (phi = 0.7): with eq. 6,
// sigma_11 - sigma_22 = 2 psi_M' (lambda^2 - 1/lambda) + phi lambda T_p(lambda); with the mixture
// form the matrix term is weighted by phi_M = 0.3.
TEST(FibreReinforcedMaterial, UniaxialAlongTheFibreMatchesTheAnalyticLaw) {
  const auto fam = equalFractionFamilies({Eigen::Vector3d::UnitX()});
  const FibreReinforcedMaterial eq6(matrix(), fam, parallel());
  const FibreReinforcedMaterial mix(matrix(), fam, parallel(), MatrixStressForm::MixtureWeighted);
  const FungIsotropic fung = FungIsotropic::muscleMatrix();
  const ParallelElement p = ParallelElement::tableI();
  for (double lambda : {0.8, 1.0, 1.1, 1.4}) {
    Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
    F(0, 0) = lambda;
    F(1, 1) = F(2, 2) = 1.0 / std::sqrt(lambda);
    const double I1 = lambda * lambda + 2.0 / lambda;
    const double matrixPart =
        2.0 * fung.A() * fung.B() * std::exp(fung.B() * (I1 - 3.0)) * (lambda * lambda - 1.0 / lambda);
    const double fibrePart = 0.7 * lambda * p.evaluate(lambda).T;
    const Eigen::Matrix3d s6 = eq6.evaluate(F).P * F.transpose(), sm = mix.evaluate(F).P * F.transpose();
    EXPECT_NEAR(s6(0, 0) - s6(1, 1), matrixPart + fibrePart, 1e-10 * fibreScale());
    EXPECT_NEAR(sm(0, 0) - sm(1, 1), 0.3 * matrixPart + fibrePart, 1e-10 * fibreScale());
  }
  EXPECT_NEAR(eq6.shearModulus(), fung.shearModulus(), 1e-12);
  EXPECT_NEAR(mix.shearModulus(), 0.3 * fung.shearModulus(), 1e-12);
}

TEST(FibreReinforcedMaterial, StressFormNames) {
  for (auto form :
       {MatrixStressForm::InFull, MatrixStressForm::FibreDirectionRemoved, MatrixStressForm::MixtureWeighted})
    EXPECT_EQ(matrixStressFormFromName(matrixStressFormName(form)), form);
  EXPECT_THROW(matrixStressFormFromName("eq6"), std::invalid_argument);
  EXPECT_THROW(FibreReinforcedMaterial(nullptr, families(), parallel()), std::invalid_argument);
  EXPECT_THROW(FibreReinforcedMaterial(matrix(), families(), nullptr), std::invalid_argument);
}
