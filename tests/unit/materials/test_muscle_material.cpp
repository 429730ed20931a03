#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

#include "MaterialConformance.hpp"
#include "materials/FibreReinforcedMaterial.hpp"
#include "materials/FungIsotropic.hpp"
#include "materials/MuscleMaterial.hpp"

using namespace glossa::materials;

namespace {
constexpr double kT0max = 668.8e3;

std::shared_ptr<const IsochoricMaterial> matrix() {
  return std::make_shared<FungIsotropic>(FungIsotropic::muscleMatrix());
}

std::vector<Eigen::Vector3d> directions() {
  return {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 1), Eigen::Vector3d(1, -2, 0.5)};
}

// Three families from three muscle groups: different T0s and curve sets.
MuscleMaterial muscle(MatrixStressForm form = MatrixStressForm::InFull) {
  const auto geometry = equalFractionFamilies(directions());
  std::vector<MuscleMaterial::Family> families{
      {geometry[0], HillMuscleFibre::tableI(1.0, physiologicalCurves())},
      {geometry[1], HillMuscleFibre::tableI(0.1, paperTableIICurves())},
      {geometry[2], HillMuscleFibre::tableI(0.5, physiologicalCurves())}};
  return MuscleMaterial(matrix(), families, form);
}

// A random state: F near identity, activation, time step and a contractile history a little
// shorter than the current fibre stretch (mostly taut series elements, some slack).
MusclePointInput randomInput(const MuscleMaterial &m, std::mt19937 &rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  MusclePointInput in;
  in.F = glossa::test::randomDeformationGradient(rng, 0.2);
  in.dt = std::pow(10.0, -4.0 + 3.0 * unit(rng));
  in.alpha = FamilyValues(m.familyCount());
  in.lambdaCOld = FamilyValues(m.familyCount());
  const Eigen::Matrix3d Cbar = std::pow(in.F.determinant(), -2.0 / 3.0) * in.F.transpose() * in.F;
  for (int f = 0; f < m.familyCount(); ++f) {
    const Eigen::Vector3d N = m.families()[f].geometry.N;
    in.alpha(f) = unit(rng);
    in.lambdaCOld(f) = std::sqrt(N.dot(Cbar * N)) * (0.97 + 0.05 * unit(rng));
  }
  return in;
}

MusclePointInput withF(MusclePointInput in, const Eigen::Matrix3d &F) {
  in.F = F;
  return in;
}
}  // namespace

// Central-FD tangent at random F, activation and lambda_c history, for each stress form.
TEST(MuscleMaterial, TangentMatchesFiniteDifferences) {
  for (auto form : {MatrixStressForm::InFull, MatrixStressForm::FibreDirectionRemoved,
                    MatrixStressForm::MixtureWeighted}) {
    const MuscleMaterial m = muscle(form);
    std::mt19937 rng(41);
    int checked = 0, taut = 0;
    for (int sample = 0; sample < 60; ++sample) {
      const MusclePointInput in = randomInput(m, rng);
      const MusclePointResponse r = m.evaluate(in);
      ASSERT_TRUE(r.ok()) << describe(r.status) << " family " << r.failedFamily;
      bool sameBranch = true;  // skip samples whose perturbations cross a taut/slack switch
      const Tangent9 fd = glossa::test::centralDifferenceTangent(
          [&](const Eigen::Matrix3d &G) {
            const MusclePointResponse q = m.evaluate(withF(in, G));
            for (int f = 0; f < m.familyCount(); ++f)
              sameBranch = sameBranch && ((q.lambdaC(f) < q.lambdaF(f)) == (r.lambdaC(f) < r.lambdaF(f)));
            return q.P;
          },
          in.F, 1e-7);
      if (!sameBranch) continue;
      ++checked;
      taut += r.status == HillSolveStatus::Taut;
      EXPECT_LT((fd - r.dPdF).norm(), 1e-6 * r.dPdF.norm() + 1e-3)
          << matrixStressFormName(form) << " sample " << sample;
    }
    EXPECT_GT(checked, 50);
    EXPECT_GT(taut, 40);
  }
}

// P = d(stored energy)/dF when lambda_c does not move (alpha = 0: the fibres are their parallel
// elements) and the passive muscle equals FibreReinforcedMaterial with the parallel element.
TEST(MuscleMaterial, PassiveMuscleIsTheFibreReinforcedMaterial) {
  const MuscleMaterial m = muscle();
  const FibreReinforcedMaterial passive(matrix(), equalFractionFamilies(directions()),
                                        std::make_shared<ParallelElement>(ParallelElement::tableI()));
  std::mt19937 rng(43);
  for (int sample = 0; sample < 20; ++sample) {
    MusclePointInput in = randomInput(m, rng);
    in.alpha.setZero();
    const MusclePointResponse r = m.evaluate(in);
    const PointResponse p = passive.evaluate(in.F);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.status, HillSolveStatus::Slack);
    EXPECT_LT((r.P - p.P).norm(), 1e-12 * kT0max);
    EXPECT_LT((r.dPdF - p.dPdF).norm(), 1e-12 * kT0max);
    EXPECT_NEAR(r.energy, p.energy, 1e-12 * kT0max);
    for (int f = 0; f < m.familyCount(); ++f) EXPECT_EQ(r.lambdaC(f), r.lambdaF(f));
  }
}

// Stress-free reference at zero activation; activation alone makes it pull.
TEST(MuscleMaterial, StressFreeReferenceAtZeroActivation) {
  const MuscleMaterial m = muscle();
  MusclePointInput in;
  in.dt = 0.005;
  in.alpha = FamilyValues::Zero(3);
  in.lambdaCOld = m.initialLambdaC();
  const MusclePointResponse r = m.evaluate(in);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.P.norm(), 0.0);
  EXPECT_EQ(r.energy, 0.0);
  for (int f = 0; f < 3; ++f) EXPECT_NEAR(r.lambdaC(f), 1.0, 1e-15);  // lambda-bar_f = |N| = 1
  in.alpha(0) = 0.5;
  const MusclePointResponse active = m.evaluate(in);
  ASSERT_TRUE(active.ok());
  EXPECT_EQ(active.status, HillSolveStatus::Taut);
  EXPECT_GT(active.T(0), 0.0);
  EXPECT_LT(active.lambdaC(0), 1.0);
  // The active family pulls along e1: deviatoric tension sigma_11 - sigma_22 = phi T (F = 1).
  EXPECT_NEAR(active.P(0, 0) - active.P(1, 1), 0.7 / 3 * active.T(0), 1e-10 * kT0max);
}

// Objectivity and insensitivity to pure dilatation, with the history response unchanged.
TEST(MuscleMaterial, ObjectiveAndIsochoric) {
  const MuscleMaterial m = muscle();
  std::mt19937 rng(47);
  for (int sample = 0; sample < 20; ++sample) {
    const MusclePointInput in = randomInput(m, rng);
    const MusclePointResponse r = m.evaluate(in);
    ASSERT_TRUE(r.ok());
    const Eigen::Matrix3d Q =
        Eigen::AngleAxisd(0.3 + sample, Eigen::Vector3d(2, -1, 1).normalized()).toRotationMatrix();
    const MusclePointResponse rq = m.evaluate(withF(in, Q * in.F));
    EXPECT_LT((rq.P - Q * r.P).norm(), 1e-9 * kT0max);
    EXPECT_NEAR(rq.energy, r.energy, 1e-9 * kT0max);
    EXPECT_LT((rq.lambdaC - r.lambdaC).norm(), 1e-13);
    const Eigen::Matrix3d Fd = 1.07 * in.F;
    const MusclePointResponse rd = m.evaluate(withF(in, Fd));
    EXPECT_LT((rd.P * Fd.transpose() - r.P * in.F.transpose()).norm(), 1e-9 * kT0max);
    EXPECT_LT((rd.lambdaC - r.lambdaC).norm(), 1e-13);
    EXPECT_NEAR((r.P * in.F.transpose()).trace(), 0.0, 1e-9 * kT0max);  // deviatoric (eq. 6)
  }
}

TEST(MuscleMaterial, InvalidInputIsReported) {
  const MuscleMaterial m = muscle();
  MusclePointInput in;
  in.alpha = FamilyValues::Zero(2);  // wrong size
  in.lambdaCOld = FamilyValues::Ones(3);
  EXPECT_EQ(m.evaluate(in).status, HillSolveStatus::InvalidInput);
  EXPECT_FALSE(m.evaluate(in).ok());
  in.alpha = FamilyValues::Constant(3, 2.0);  // alpha out of range
  const MusclePointResponse r = m.evaluate(in);
  EXPECT_EQ(r.status, HillSolveStatus::InvalidInput);
  EXPECT_EQ(r.failedFamily, 0);
  std::vector<MuscleMaterial::Family> tooMany(
      kMaxFibreFamilies + 1,
      {FibreFamily{Eigen::Vector3d::UnitX(), 0.01}, HillMuscleFibre::tableI(1.0, physiologicalCurves())});
  EXPECT_THROW(MuscleMaterial(matrix(), tooMany), std::invalid_argument);
  EXPECT_THROW(MuscleMaterial(nullptr, {}), std::invalid_argument);
}

// The same at vanishing activation (a step just past the start of a neural-input ramp): every
// point solves and its tangent is the finite-difference one.
TEST(MuscleMaterial, TangentMatchesFiniteDifferencesAtVanishingActivation) {
  const MuscleMaterial m = muscle();
  std::mt19937 rng(43);
  for (double alpha : {1e-16, 1e-300, 4.9e-324, 0.0})
    for (int sample = 0; sample < 10; ++sample) {
      MusclePointInput in = randomInput(m, rng);
      in.alpha.setConstant(alpha);
      const MusclePointResponse r = m.evaluate(in);
      ASSERT_TRUE(r.ok()) << describe(r.status) << " family " << r.failedFamily << " alpha " << alpha;
      const Tangent9 fd = glossa::test::centralDifferenceTangent(
          [&](const Eigen::Matrix3d &G) { return m.evaluate(withF(in, G)).P; }, in.F, 1e-7);
      EXPECT_LT((fd - r.dPdF).norm(), 1e-6 * r.dPdF.norm() + 1e-3) << "alpha " << alpha << " sample " << sample;
    }
}
