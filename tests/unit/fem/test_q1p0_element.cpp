// Element-level checks of the condensed Q1-P0 kernel: finite-difference residual and tangent,
// rigid-body null space, and the patch test.
#include <random>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "fem/Q1P0Element.hpp"
#include "UnitCube.hpp"
#include "materials/NeoHookean.hpp"
#include "materials/VolumetricEnergy.hpp"

using namespace glossa;
using fem::ElementVector;
using fem::NodeMatrix;

namespace {

NodeMatrix unitHex(double h = 1.0) {
  NodeMatrix X;
  for (int a = 0; a < 8; ++a) X.row(a) = 0.5 * h * (fem::hexNodeXi(a).array() + 1.0).matrix().transpose();
  return X;
}

NodeMatrix distortedHex(std::mt19937 &rng) {
  std::uniform_real_distribution<double> d(-0.15, 0.15);
  NodeMatrix X = unitHex(1e-3);
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) X(a, i) += 1e-3 * d(rng);
  return X;
}

struct Fixture {
  materials::NeoHookean iso{80.194e6};
  materials::VolumetricEnergy vol{materials::VolumetricEnergy::Form::SimoTaylor,
                                  materials::bulkModulus(80.194e6, 0.45)};
};

template <class Eval> void expectConsistentTangent(Eval &&eval, const NodeMatrix &u, double h) {
  const auto r = eval(u);
  ASSERT_TRUE(r.valid);
  fem::ElementMatrix fdK;
  ElementVector fdR;
  for (int c = 0; c < 24; ++c) {
    NodeMatrix up = u, um = u;
    up(c / 3, c % 3) += h;
    um(c / 3, c % 3) -= h;
    const auto rp = eval(up), rm = eval(um);
    fdK.col(c) = (rp.residual - rm.residual) / (2 * h);
    fdR(c) = (rp.energy - rm.energy) / (2 * h);
  }
  EXPECT_LT((fdR - r.residual).norm(), 1e-6 * r.residual.norm()) << "R != dPi/du";
  EXPECT_LT((fdK - r.tangent).norm(), 1e-6 * r.tangent.norm()) << "K != dR/du";
  EXPECT_LT((r.tangent - r.tangent.transpose()).norm(), 1e-10 * r.tangent.norm());
}

} // namespace

TEST(Q1P0Element, TangentMatchesFiniteDifferences) {
  Fixture f;
  std::mt19937 rng(7);
  for (int sample = 0; sample < 5; ++sample) {
    const NodeMatrix X = distortedHex(rng);
    const NodeMatrix u = fem::testing::randomNodalDisplacement(rng, 1e-4);
    const double lambda = 1e5 * sample;
    expectConsistentTangent(
        [&](const NodeMatrix &v) { return fem::evaluateQ1P0(X, v, f.iso, f.vol, lambda); }, u, 1e-9);
  }
}

TEST(Q1P0Element, PlainQ1TangentMatchesFiniteDifferences) {
  Fixture f;
  std::mt19937 rng(11);
  const NodeMatrix X = distortedHex(rng);
  const NodeMatrix u = fem::testing::randomNodalDisplacement(rng, 1e-4);
  expectConsistentTangent([&](const NodeMatrix &v) { return fem::evaluatePlainQ1(X, v, f.iso, f.vol); },
                          u, 1e-9);
}

TEST(Q1P0Element, RigidBodyModesAreInTheNullSpace) {
  Fixture f;
  std::mt19937 rng(3);
  const NodeMatrix X = distortedHex(rng);
  const auto r = fem::evaluateQ1P0(X, NodeMatrix::Zero(), f.iso, f.vol, 0.0);
  ASSERT_TRUE(r.valid);
  // Three translations and three infinitesimal rotations.
  for (int mode = 0; mode < 6; ++mode) {
    ElementVector m;
    for (int a = 0; a < 8; ++a) {
      Eigen::Vector3d v = Eigen::Vector3d::Zero();
      if (mode < 3) v(mode) = 1.0;
      else v = Eigen::Vector3d::Unit(mode - 3).cross(Eigen::Vector3d(X.row(a)));
      m.segment<3>(3 * a) = v;
    }
    m.normalize();
    EXPECT_LT((r.tangent * m).norm(), 1e-9 * r.tangent.norm()) << "mode " << mode;
  }
  // A finite rotation is stress free: zero residual, theta = 1.
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(1.0, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  NodeMatrix u;
  for (int a = 0; a < 8; ++a) u.row(a) = (Q * X.row(a).transpose() - X.row(a).transpose()).transpose();
  const auto rr = fem::evaluateQ1P0(X, u, f.iso, f.vol, 0.0);
  EXPECT_LT(rr.residual.norm(), 1e-9 * r.tangent.norm() * 1e-3);
  EXPECT_NEAR(rr.theta, 1.0, 1e-12);
}

// Patch test: 2x2x2 elements around a displaced interior node; a homogeneous deformation
// u = (F - I) X must give zero force at the interior node, theta = det F in every element,
// and the analytic Cauchy stress.
TEST(Q1P0Element, PatchTestHomogeneousDeformation) {
  Fixture f;
  const double h = 0.5e-3;
  auto nodeId = [](int i, int j, int k) { return i + 3 * (j + 3 * k); };
  std::vector<Eigen::Vector3d> nodes(27);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) nodes[nodeId(i, j, k)] = h * Eigen::Vector3d(i, j, k);
  nodes[nodeId(1, 1, 1)] += Eigen::Vector3d(0.11, -0.07, 0.05) * h; // distort the patch

  Eigen::Matrix3d F;
  F << 1.05, 0.02, -0.03, 0.01, 0.97, 0.04, 0.00, -0.02, 1.01;
  const double lambda = 2.5e5;
  Eigen::Vector3d interiorForce = Eigen::Vector3d::Zero();
  const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                            {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const double J = F.determinant();
  const double p = f.vol.dU(J) + lambda;
  const auto iso = f.iso.evaluate(F);
  const Eigen::Matrix3d sigmaExact = (iso.P * F.transpose()) / J + p * Eigen::Matrix3d::Identity();
  for (int ek = 0; ek < 2; ++ek)
    for (int ej = 0; ej < 2; ++ej)
      for (int ei = 0; ei < 2; ++ei) {
        NodeMatrix X, u;
        int interiorLocal = -1;
        for (int a = 0; a < 8; ++a) {
          const int n = nodeId(ei + corner[a][0], ej + corner[a][1], ek + corner[a][2]);
          X.row(a) = nodes[n].transpose();
          u.row(a) = ((F - Eigen::Matrix3d::Identity()) * nodes[n]).transpose();
          if (n == nodeId(1, 1, 1)) interiorLocal = a;
        }
        const auto r = fem::evaluateQ1P0(X, u, f.iso, f.vol, lambda);
        ASSERT_TRUE(r.valid);
        EXPECT_NEAR(r.theta, J, 1e-12);
        EXPECT_NEAR(r.pressure, p, 1e-9 * std::abs(p));
        EXPECT_LT((r.cauchyMean - sigmaExact).norm(), 1e-9 * sigmaExact.norm());
        interiorForce += r.residual.segment<3>(3 * interiorLocal);
      }
  EXPECT_LT(interiorForce.norm(), 1e-9 * sigmaExact.norm() * h * h);
}

TEST(Q1P0Element, InvertedElementIsReportedNotEvaluated) {
  Fixture f;
  const NodeMatrix X = unitHex(1e-3);
  NodeMatrix u = NodeMatrix::Zero();
  u(6, 0) = -3e-3; // push a node through the element
  const auto r = fem::evaluateQ1P0(X, u, f.iso, f.vol, 0.0);
  EXPECT_FALSE(r.valid);
  EXPECT_LE(r.minJ, 0.0);
}

// The three-field iterate: at a consistent base (theta_b = v/V) it is the exact condensation,
// and its tangent is the derivative of its residual there.
TEST(Q1P0Element, MixedIterateAtConsistentBaseEqualsExactCondensation) {
  Fixture f;
  std::mt19937 rng(5);
  const NodeMatrix X = distortedHex(rng);
  const NodeMatrix u = fem::testing::randomNodalDisplacement(rng, 1e-4);
  const double lambda = 3e5;
  const fem::MixedBase base = fem::mixedBase(X, u, nullptr, f.vol, lambda);
  ASSERT_TRUE(base.valid);
  const auto exact = fem::evaluateQ1P0(X, u, f.iso, f.vol, lambda);
  const auto mixed = fem::evaluateQ1P0Mixed(X, u, base, f.iso, f.vol, lambda, false);
  const auto trial = fem::evaluateQ1P0Mixed(X, u, base, f.iso, f.vol, lambda, true);
  EXPECT_LT((trial.residual - mixed.residual).norm(), 1e-12 * exact.residual.norm());
  EXPECT_LT((mixed.residual - exact.residual).norm(), 1e-12 * exact.residual.norm());
  EXPECT_LT((mixed.tangent - exact.tangent).norm(), 1e-12 * exact.tangent.norm());
  EXPECT_NEAR(mixed.pressure, exact.pressure, 1e-9 * std::abs(exact.pressure));
  // K = dR/du at the base: perturb u with the base held fixed.
  fem::ElementMatrix fdK;
  const double h = 1e-9;
  for (int c = 0; c < 24; ++c) {
    NodeMatrix up = u, um = u;
    up(c / 3, c % 3) += h;
    um(c / 3, c % 3) -= h;
    fdK.col(c) = (fem::evaluateQ1P0Mixed(X, up, base, f.iso, f.vol, lambda, true).residual -
                  fem::evaluateQ1P0Mixed(X, um, base, f.iso, f.vol, lambda, true).residual) / (2 * h);
  }
  EXPECT_LT((fdK - mixed.tangent).norm(), 1e-6 * mixed.tangent.norm());
}

// Away from the base, theta is the linearised volume and p the linearised U', so one Newton
// step of the three-field equations on one element lands where the linearisation says.
TEST(Q1P0Element, MixedIterateExtrapolatesLinearly) {
  Fixture f;
  std::mt19937 rng(9);
  const NodeMatrix X = distortedHex(rng);
  const NodeMatrix u0 = fem::testing::randomNodalDisplacement(rng, 1e-4);
  const NodeMatrix du = fem::testing::randomNodalDisplacement(rng, 1e-5);
  const fem::MixedBase base = fem::mixedBase(X, u0, nullptr, f.vol, 0.0);
  const auto r = fem::evaluateQ1P0Mixed(X, u0 + du, base, f.iso, f.vol, 0.0, true);
  double dv = 0.0;
  for (int a = 0; a < 8; ++a) dv += base.g.segment<3>(3 * a).dot(du.row(a).transpose());
  const double V = r.referenceVolume;
  EXPECT_NEAR(r.theta, (base.v + dv) / V, 1e-14);
  EXPECT_NEAR(r.pressure, f.vol.dU(base.theta) + f.vol.d2U(base.theta) * (r.theta - base.theta),
              1e-9 * std::abs(r.pressure) + 1e-6);
  // The next base carries that dilatation iterate forward.
  const fem::MixedBase next = fem::mixedBase(X, u0 + du, &base, f.vol, 0.0);
  EXPECT_NEAR(next.theta, r.theta, 1e-14);
  EXPECT_NEAR(next.pressure, r.pressure, 1e-12 * std::abs(r.pressure));
  // At the new iterate its own state is used: same residual as the trial evaluation.
  const auto at = fem::evaluateQ1P0Mixed(X, u0 + du, next, f.iso, f.vol, 0.0, false);
  EXPECT_LT((at.residual - r.residual).norm(), 1e-12 * r.residual.norm());
}

// The coupling column of the uncondensed system is the derivative of the current volume: checked
// against central differences of v(u) and against v = V det F for a homogeneous deformation.
TEST(Q1P0Element, VolumeGradientIsTheDerivativeOfTheCurrentVolume) {
  std::mt19937 rng(7);
  const NodeMatrix X = distortedHex(rng);
  const NodeMatrix u = fem::testing::randomNodalDisplacement(rng, 1e-4);
  double V = 0.0, v = 0.0;
  ElementVector g;
  ASSERT_TRUE(fem::elementVolumeGradient(X, u, V, v, g));
  const double h = 1e-9;
  for (int k = 0; k < 24; ++k) {
    NodeMatrix up = u, um = u;
    up(k / 3, k % 3) += h;
    um(k / 3, k % 3) -= h;
    double Vp, vp, Vm, vm;
    ElementVector gp, gm;
    ASSERT_TRUE(fem::elementVolumeGradient(X, up, Vp, vp, gp));
    ASSERT_TRUE(fem::elementVolumeGradient(X, um, Vm, vm, gm));
    EXPECT_NEAR(g(k), (vp - vm) / (2 * h), 1e-7 * g.norm()) << k;
  }
  Eigen::Matrix3d F;
  F << 1.1, 0.05, 0.0, -0.02, 0.95, 0.03, 0.01, 0.0, 1.02;
  const NodeMatrix uh = X * (F - Eigen::Matrix3d::Identity()).transpose();
  ASSERT_TRUE(fem::elementVolumeGradient(X, uh, V, v, g));
  EXPECT_NEAR(v, V * F.determinant(), 1e-12 * V);
}

namespace {
// A distorted element at a small random displacement, and its displacement part with the tangent.
struct PartSample : Fixture {
  explicit PartSample(unsigned seed)
      : rng(seed), X(distortedHex(rng)), u(fem::testing::randomNodalDisplacement(rng, 1e-4)), law(iso),
        part(fem::evaluateDisplacementPart(X, u, law, fem::Q1P0Output::ResidualAndTangent)) {}
  std::mt19937 rng;
  NodeMatrix X, u;
  fem::UniformPointLaw law;
  fem::Q1P0DisplacementPart part;
};
} // namespace

// The volume's Hessian in the displacement part (the pressure's geometric stiffness per unit
// pressure) is the derivative of its volume gradient: central differences of g(u).
TEST(Q1P0Element, VolumeHessianIsTheDerivativeOfTheVolumeGradient) {
  const PartSample sample(11);
  const NodeMatrix &X = sample.X, &u = sample.u;
  const fem::Q1P0DisplacementPart &part = sample.part;
  const fem::UniformPointLaw &law = sample.law;
  ASSERT_TRUE(part.valid && part.withTangent);
  fem::ElementMatrix fd;
  const double h = 1e-9;
  for (int c = 0; c < 24; ++c) {
    NodeMatrix up = u, um = u;
    up(c / 3, c % 3) += h;
    um(c / 3, c % 3) -= h;
    fd.col(c) = (fem::evaluateDisplacementPart(X, up, law, fem::Q1P0Output::ResidualOnly).volumeGradient -
                 fem::evaluateDisplacementPart(X, um, law, fem::Q1P0Output::ResidualOnly).volumeGradient) /
                (2 * h);
  }
  EXPECT_LT((fd - part.volumeHessian).norm(), 1e-6 * part.volumeHessian.norm());
  EXPECT_LT((part.volumeHessian - part.volumeHessian.transpose()).norm(), 1e-12 * part.volumeHessian.norm());
}

// One displacement part finishes to the element at any multiplier and base, bit for bit as a
// whole evaluation there: what lets an Uzawa update reuse the point laws of the state it starts at.
TEST(Q1P0Element, ADisplacementPartFinishesAtEveryMultiplierAsAWholeEvaluation) {
  const PartSample f(13);
  const NodeMatrix &X = f.X, &u = f.u;
  const fem::Q1P0DisplacementPart &part = f.part;
  const fem::UniformPointLaw &law = f.law;
  const fem::MixedBase base = fem::mixedBase(X, 0.9 * u, nullptr, f.vol, 1e4);
  for (const double lambda : {0.0, 2e5, -7e4}) {
    const auto whole = fem::evaluateQ1P0(X, u, f.iso, f.vol, lambda);
    const auto finished = fem::finishQ1P0(part, f.vol, lambda, fem::Q1P0Output::ResidualAndTangent);
    EXPECT_TRUE(whole.residual == finished.residual && whole.tangent == finished.tangent) << lambda;
    EXPECT_EQ(whole.energy, finished.energy);
    EXPECT_EQ(whole.pressure, finished.pressure);
    const auto wholeMixed = fem::evaluateQ1P0Mixed(X, u, base, f.iso, f.vol, lambda, true);
    const auto finishedMixed =
        fem::finishQ1P0Mixed(part, u, base, f.vol, lambda, true, fem::Q1P0Output::ResidualAndTangent);
    EXPECT_TRUE(wholeMixed.residual == finishedMixed.residual && wholeMixed.tangent == finishedMixed.tangent)
        << lambda;
  }
  // A part formed for the residual alone cannot give a tangent.
  const auto residualOnly = fem::evaluateDisplacementPart(X, u, law, fem::Q1P0Output::ResidualOnly);
  EXPECT_THROW(fem::finishQ1P0(residualOnly, f.vol, 0.0, fem::Q1P0Output::ResidualAndTangent), std::logic_error);
}

namespace {
// A symmetric law (neo-Hookean, its A symmetric to round-off) whose tangent gets an unsymmetric part
// from point `first` on: the element kernel adds a symmetric point's upper blocks only, so a law
// like the eq. 5 fibre stress form, unsymmetric at some points, must still get every block right.
class SkewedFromPoint final : public fem::QuadraturePointLaw {
public:
  SkewedFromPoint(const materials::IsochoricMaterial &m, int first) : m_(m), first_(first) {}
  bool evaluate(int q, const Eigen::Matrix3d &F, materials::PointResponse &out) const override {
    out = m_.evaluate(F);
    if (q >= first_)
      for (int r = 0; r < 9; ++r)
        for (int c = 0; c < r; ++c) out.dPdF(r, c) += 1e5 * (1 + r + 2 * c + q);
    return true;
  }

private:
  const materials::IsochoricMaterial &m_;
  int first_;
};

// sum_q dV B^T A_q B with the dense 9x24 gradient operator B(iJ, 3b+k) = delta_ik dN_b/dX_J.
fem::ElementMatrix denseTangent(const NodeMatrix &X, const NodeMatrix &u, const fem::QuadraturePointLaw &law) {
  fem::ElementMatrix K = fem::ElementMatrix::Zero();
  const auto &rule = fem::gaussHex2();
  for (int q = 0; q < 8; ++q) {
    Eigen::Matrix<double, 8, 3> dN;
    double detJ0 = 0.0;
    EXPECT_TRUE(fem::hexGradients(X, rule[q].xi, dN, detJ0));
    materials::PointResponse r;
    law.evaluate(q, Eigen::Matrix3d::Identity() + u.transpose() * dN, r);
    Eigen::Matrix<double, 9, 24> B = Eigen::Matrix<double, 9, 24>::Zero();
    for (int b = 0; b < 8; ++b)
      for (int i = 0; i < 3; ++i)
        for (int J = 0; J < 3; ++J) B(3 * i + J, 3 * b + i) = dN(b, J);
    K += detJ0 * rule[q].weight * B.transpose() * r.dPdF * B;
  }
  return K;
}
} // namespace

// The element tangent is sum B^T A B (the dense product, an independent reference) for a symmetric
// law (upper blocks mirrored), a law unsymmetric at every point, and one unsymmetric from the
// fourth point on (the blocks of the first three completed before the rest are added in full).
TEST(Q1P0Element, TangentIsBTransposeABForSymmetricAndUnsymmetricLaws) {
  const PartSample f(17);
  for (const int first : {8, 0, 3}) {
    const SkewedFromPoint law(f.iso, first);
    const auto part = fem::evaluateDisplacementPart(f.X, f.u, law, fem::Q1P0Output::ResidualAndTangent);
    ASSERT_TRUE(part.valid && part.withTangent);
    const fem::ElementMatrix reference = denseTangent(f.X, f.u, law);
    EXPECT_LT((part.tangent - reference).norm(), 1e-13 * reference.norm()) << first;
    const double skew = (reference - reference.transpose()).norm() / reference.norm();
    if (first == 8) EXPECT_LT((part.tangent - part.tangent.transpose()).norm(), 1e-15 * reference.norm());
    else EXPECT_GT(skew, 1e-3) << first;
  }
}
