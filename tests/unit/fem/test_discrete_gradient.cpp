// The energy-conserving step's element correction (fem/DiscreteGradient) on the condensed Q1-P0
// element with a neo-Hookean matrix, compressible and nearly incompressible: with it the work of
// the step's force equals the stored energy's change to round-off (the property that makes the
// step conserve energy), while it sums to zero over the nodes, vanishes for a translation, and
// vanishes with the step at second order (so the scheme stays consistent and second order).
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "fem/DiscreteGradient.hpp"
#include "UnitCube.hpp"
#include "materials/NeoHookean.hpp"
#include "materials/VolumetricEnergy.hpp"

using namespace glossa;
using fem::ElementVector;
using fem::NodeMatrix;

// Names of their own: the unit tests of this folder build as one unity source.
namespace {

NodeMatrix stepCube(std::mt19937 &rng) {
  std::uniform_real_distribution<double> d(-0.15, 0.15);
  NodeMatrix X;
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) X(a, i) = 0.01 * (0.5 * (fem::hexNodeXi(a)(i) + 1.0) + d(rng));
  return X;
}


struct StepElement {
  materials::NeoHookean iso{1e4};
  materials::VolumetricEnergy vol;
  double lambda;
  NodeMatrix X;
  fem::Q1P0Result at(const NodeMatrix &u) const {
    return fem::evaluateQ1P0(X, u, iso, vol, lambda, fem::Q1P0Output::ResidualOnly);
  }
  // The corrected force of a step from u0 to u1, and the correction.
  fem::DiscreteGradientCorrection step(const NodeMatrix &u0, const NodeMatrix &u1, ElementVector &force) const {
    const auto r0 = at(u0), r1 = at(u1);
    EXPECT_TRUE(r0.valid && r1.valid);
    const ElementVector mean = 0.5 * (r0.residual + r1.residual);
    const auto c = fem::discreteGradientCorrection(fem::flattenNodes(u1 - u0), r0.energy, r1.energy, mean);
    force = mean + c.force;
    return c;
  }
};

StepElement stepElement(double nu, double lambda, std::mt19937 &rng) {
  return {materials::NeoHookean{1e4},
          materials::VolumetricEnergy{materials::VolumetricEnergy::Form::SimoTaylor, materials::bulkModulus(1e4, nu)},
          lambda, stepCube(rng)};
}

} // namespace

TEST(DiscreteGradient, TheStepsWorkIsTheStoredEnergysChange) {
  std::mt19937 rng(11);
  for (double nu : {0.3, 0.49999})
    for (int sample = 0; sample < 6; ++sample) {
      const StepElement e = stepElement(nu, sample * 50.0, rng);
      const NodeMatrix u0 = fem::testing::randomNodalDisplacement(rng, 1e-3), u1 = u0 + fem::testing::randomNodalDisplacement(rng, 5e-4);
      ElementVector force;
      const auto c = e.step(u0, u1, force);
      const double dW = e.at(u1).energy - e.at(u0).energy;
      const double trapezoidal = 0.5 * (e.at(u0).residual + e.at(u1).residual).dot(fem::flattenNodes(u1 - u0));
      // Without the correction the trapezoidal work misses dW by the quadrature error.
      EXPECT_GT(std::abs(trapezoidal - dW), 1e-9 * std::abs(dW)) << "nu " << nu;
      EXPECT_NEAR(force.dot(fem::flattenNodes(u1 - u0)), dW, 1e-12 * (std::abs(e.at(u0).energy) + std::abs(e.at(u1).energy)))
          << "nu " << nu << " sample " << sample;
      EXPECT_NE(c.coefficient, 0.0);
      for (int i = 0; i < 3; ++i) {
        double net = 0.0;
        for (int a = 0; a < 8; ++a) net += c.force(3 * a + i);
        EXPECT_NEAR(net, 0.0, 1e-14 * c.force.norm()) << "the correction's net force";
      }
    }
}

TEST(DiscreteGradient, ARigidTranslationGetsNoCorrection) {
  std::mt19937 rng(12);
  const StepElement e = stepElement(0.45, 0.0, rng);
  const NodeMatrix u0 = fem::testing::randomNodalDisplacement(rng, 1e-3);
  NodeMatrix u1 = u0;
  for (int a = 0; a < 8; ++a) u1.row(a) += Eigen::RowVector3d(2e-3, -1e-3, 5e-4);
  ElementVector force;
  const auto c = e.step(u0, u1, force);
  EXPECT_EQ(c.coefficient, 0.0);
  EXPECT_EQ(c.force.norm(), 0.0);
}

TEST(DiscreteGradient, TheCorrectionVanishesWithTheStepAtSecondOrder) {
  // u1 = u0 + s w: the quadrature error is O(s^3) and |d|^2 is O(s^2), so c d is O(s^2) against
  // the force's O(1): halving s quarters it.
  std::mt19937 rng(13);
  for (double nu : {0.3, 0.49999}) {
    const StepElement e = stepElement(nu, 0.0, rng);
    const NodeMatrix u0 = fem::testing::randomNodalDisplacement(rng, 1e-3), w = fem::testing::randomNodalDisplacement(rng, 1e-3);
    double previous = 0.0;
    // From s = 1/16 on: the asymptotic range, where the cubic term of the quadrature error leads.
    for (int k = 4; k < 9; ++k) {
      const double s = std::pow(0.5, k);
      ElementVector force;
      const double size = e.step(u0, u0 + s * w, force).force.norm();
      if (k > 4) {
        const double order = std::log2(previous / size);
        EXPECT_NEAR(order, 2.0, 0.15) << "nu " << nu << " s " << s;
      }
      previous = size;
    }
  }
}

TEST(DiscreteGradient, ItsTangentIsTheProjectionThatRemovesTranslations) {
  fem::ElementMatrix K = fem::ElementMatrix::Zero();
  fem::addTranslationFreeIdentity(K, 2.5);
  ElementVector translation = ElementVector::Zero();
  for (int a = 0; a < 8; ++a) translation(3 * a + 1) = 1.0;
  EXPECT_LT((K * translation).norm(), 1e-15);
  std::mt19937 rng(14);
  const ElementVector du = fem::flattenNodes(fem::testing::randomNodalDisplacement(rng, 1.0));
  ElementVector d = du;
  for (int i = 0; i < 3; ++i) {
    double mean = 0.0;
    for (int a = 0; a < 8; ++a) mean += du(3 * a + i) / 8.0;
    for (int a = 0; a < 8; ++a) d(3 * a + i) -= mean;
  }
  EXPECT_LT((K * du - 2.5 * d).norm(), 1e-14 * d.norm()); // d/du (c d) at fixed c
}
