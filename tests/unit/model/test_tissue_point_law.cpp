// The muscle point law inside the Q1-P0 kernel: the element tangent is the central finite
// difference of the element residual with the fibre directions, activation and lambda_c history
// of the element (the implicit lambda_c solve differentiated consistently through the kernel);
// the recorded lambda_c equals the point law's own; a failed local solve marks the element
// invalid instead of returning numbers.
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "fem/Q1P0Element.hpp"
#include "materials/ContractileCurveSets.hpp"
#include "materials/FungIsotropic.hpp"
#include "model/TissuePointLaw.hpp"

using namespace glossa;
using fem::NodeMatrix;

namespace {
materials::MuscleMaterial twoFamilies() {
  auto matrix = std::make_shared<materials::FungIsotropic>(materials::FungIsotropic::muscleMatrix());
  const auto geometry = materials::equalFractionFamilies({Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()});
  return materials::MuscleMaterial(matrix, {{geometry[0], materials::HillMuscleFibre::tableI(0.3, materials::physiologicalCurves())},
                                            {geometry[1], materials::HillMuscleFibre::tableI(1.0, materials::physiologicalCurves())}});
}

NodeMatrix unitCube() {
  NodeMatrix X;
  X << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1;
  return 1e-3 * X;
}

struct Fixture {
  materials::MuscleMaterial law = twoFamilies();
  materials::VolumetricEnergy volumetric{materials::VolumetricEnergy::Form::SimoTaylor, 2e5};
  materials::FamilyDirections N;
  materials::FamilyValues alpha;
  std::array<double, 16> lambdaCOld{};
  std::array<const double *, 8> history{};
  // What the element gives point q: its F, the fixture's activation and history, directions N.
  materials::MusclePointInput pointInput(int q, const Eigen::Matrix3d &F, const materials::FamilyDirections &N) const {
    materials::MusclePointInput in;
    in.F = F;
    in.dt = 0.005;
    in.alpha = alpha;
    in.lambdaCOld = Eigen::Vector2d(lambdaCOld[2 * q], lambdaCOld[2 * q + 1]);
    in.directions = N;
    return in;
  }
  Fixture() {
    N.resize(3, 2);
    N.col(0) = Eigen::Vector3d(1, 1, 0).normalized(); // the element's own directions, not the law's
    N.col(1) = Eigen::Vector3d(0, 0.6, 0.8);
    alpha.resize(2);
    alpha << 0.7, 0.4;
    for (int q = 0; q < 8; ++q) {
      lambdaCOld[2 * q] = 1.0 - 0.002 * q;
      lambdaCOld[2 * q + 1] = 0.995 + 0.001 * q;
      history[q] = &lambdaCOld[2 * q];
    }
  }
};
// Central differences (step 1e-10 m) of the element residual: column c is d residual / d u_c.
template <class Evaluate>
fem::ElementMatrix centralDifferenceTangent(const Evaluate &eval, const NodeMatrix &u) {
  fem::ElementMatrix fd;
  const double h = 1e-10;
  for (int c = 0; c < 24; ++c) {
    NodeMatrix up = u, um = u;
    up(c / 3, c % 3) += h;
    um(c / 3, c % 3) -= h;
    fd.col(c) = (eval(up).residual - eval(um).residual) / (2 * h);
  }
  return fd;
}
} // namespace

TEST(TissuePointLaw, ElementTangentMatchesFiniteDifferences) {
  Fixture f;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const NodeMatrix X = unitCube();
  for (int sample = 0; sample < 4; ++sample) {
    NodeMatrix u;
    for (int i = 0; i < 24; ++i) u(i / 3, i % 3) = 5e-5 * unit(rng) + (i % 3 == 0 ? 2e-5 * X(i / 3, 0) / 1e-3 : 0.0);
    const model::TissuePointLaw law(f.law, f.N, f.alpha, 0.005, f.history);
    auto eval = [&](const NodeMatrix &v) { return fem::evaluateQ1P0(X, v, law, f.volumetric, 50.0); };
    const auto r = eval(u);
    ASSERT_TRUE(r.valid);
    EXPECT_LT((centralDifferenceTangent(eval, u) - r.tangent).norm(), 1e-5 * r.tangent.norm()) << "sample " << sample;
  }
}

TEST(TissuePointLaw, RecordsThePointLawsContractileStretch) {
  Fixture f;
  NodeMatrix u = NodeMatrix::Zero();
  u.col(0) = 0.03 * unitCube().col(0); // 3 % stretch along x
  model::ElementMuscleResponse record;
  const model::TissuePointLaw law(f.law, f.N, f.alpha, 0.005, f.history, &record);
  ASSERT_TRUE(fem::evaluateQ1P0(unitCube(), u, law, f.volumetric, 0.0).valid);
  std::array<Eigen::Matrix3d, 8> F;
  std::array<double, 8> dV;
  ASSERT_TRUE(fem::quadratureDeformationGradients(unitCube(), u, F, dV));
  for (int q = 0; q < 8; ++q) {
    const auto direct = f.law.evaluate(f.pointInput(q, F[q], f.N));
    EXPECT_EQ(record.lambdaC[q], direct.lambdaC) << q;
    EXPECT_EQ(record.T[q], direct.T) << q;
  }
}

TEST(TissuePointLaw, FailedLocalSolveInvalidatesTheElement) {
  Fixture f;
  f.alpha(1) = 1.5; // outside [0, 1]: the Hill solve refuses it
  model::ElementMuscleResponse record;
  const model::TissuePointLaw law(f.law, f.N, f.alpha, 0.005, f.history, &record);
  const auto r = fem::evaluateQ1P0(unitCube(), NodeMatrix::Zero(), law, f.volumetric, 0.0);
  EXPECT_FALSE(r.valid);
  EXPECT_TRUE(r.lawFailed);
  EXPECT_EQ(record.status, materials::HillSolveStatus::InvalidInput);
}

// Directions varying inside the element (polylines sampled at the quadrature points): the
// tangent is still the central difference of the residual, each point uses its own directions
// (checked against the point law evaluated directly), and eight copies of the element's
// directions give the element-constant result bit for bit.
TEST(TissuePointLaw, PerPointDirections) {
  Fixture f;
  std::array<materials::FamilyDirections, 8> perPoint;
  for (int q = 0; q < 8; ++q) {
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.2 * q, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    perPoint[q] = R * f.N;
  }
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const NodeMatrix X = unitCube();
  NodeMatrix u;
  for (int i = 0; i < 24; ++i) u(i / 3, i % 3) = 5e-5 * unit(rng) + (i % 3 == 0 ? 2e-5 * X(i / 3, 0) / 1e-3 : 0.0);
  model::ElementMuscleResponse record;
  const model::TissuePointLaw law(f.law, f.N, f.alpha, 0.005, f.history, &record, &perPoint);
  auto eval = [&](const NodeMatrix &v) { return fem::evaluateQ1P0(X, v, law, f.volumetric, 50.0); };
  const auto r = eval(u);
  ASSERT_TRUE(r.valid);
  EXPECT_LT((centralDifferenceTangent(eval, u) - r.tangent).norm(), 1e-5 * r.tangent.norm());

  eval(u); // the record holds the last evaluation: at u
  std::array<Eigen::Matrix3d, 8> F;
  std::array<double, 8> dV;
  ASSERT_TRUE(fem::quadratureDeformationGradients(X, u, F, dV));
  for (int q = 0; q < 8; ++q) {
    EXPECT_EQ(record.lambdaF[q], f.law.evaluate(f.pointInput(q, F[q], perPoint[q])).lambdaF) << q;
  }
  // The rotated directions change the fibre stretches, so the check above can tell them apart.
  EXPECT_GT((record.lambdaF[7] - record.lambdaF[0]).norm(), 1e-6);

  std::array<materials::FamilyDirections, 8> same;
  same.fill(f.N);
  const model::TissuePointLaw constant(f.law, f.N, f.alpha, 0.005, f.history);
  const model::TissuePointLaw copies(f.law, f.N, f.alpha, 0.005, f.history, nullptr, &same);
  const auto a = fem::evaluateQ1P0(X, u, constant, f.volumetric, 50.0);
  const auto b = fem::evaluateQ1P0(X, u, copies, f.volumetric, 50.0);
  EXPECT_EQ((a.residual - b.residual).norm(), 0.0);
  EXPECT_EQ((a.tangent - b.tangent).norm(), 0.0);
}
