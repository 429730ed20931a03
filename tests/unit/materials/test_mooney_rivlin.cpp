// The uncoupled Mooney-Rivlin (two- and five-parameter) and Yeoh laws: finite-difference
// tangents and the other conformance checks, the invariant I2-bar against its definition,
// incompressible uniaxial stretch and simple shear against their closed forms, and FEBio's
// verification case mi03 (one hexahedron, c1 = 1, c2 = 10, k = 100, U = k/2 ln^2 J, compressed to
// lambda = 0.2 with free lateral faces: lateral stretch 1.416623835, J = 0.40136462).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "MaterialConformance.hpp"
#include "materials/IsochoricInvariant.hpp"
#include "materials/MooneyRivlin.hpp"
#include "materials/VolumetricEnergy.hpp"
#include "materials/Yeoh.hpp"

using glossa::materials::MooneyRivlin;
using glossa::materials::MooneyRivlinParameters;
using glossa::materials::VolumetricEnergy;
using glossa::materials::Yeoh;

namespace {
MooneyRivlinParameters twoParameter(double C10, double C01) {
  MooneyRivlinParameters c;
  c.C10 = C10;
  c.C01 = C01;
  return c;
}

MooneyRivlinParameters fiveParameter() {
  MooneyRivlinParameters c;
  c.C10 = 1037.0;
  c.C01 = 250.0;
  c.C11 = 120.0;
  c.C20 = 486.0;
  c.C02 = 60.0;
  return c;
}

// psi's partial derivatives in I1-bar and I2-bar, written out independently of the law.
struct Partials {
  double W1, W2;
};
Partials partials(const MooneyRivlinParameters &c, double I1, double I2) {
  const double a = I1 - 3.0, b = I2 - 3.0;
  return {c.C10 + c.C11 * b + 2.0 * c.C20 * a, c.C01 + c.C11 * a + 2.0 * c.C02 * b};
}
} // namespace

TEST(IsochoricI2, ValueAndDerivativesAgainstItsDefinitionAndDifferences) {
  std::mt19937 rng(5u);
  for (int sample = 0; sample < 20; ++sample) {
    const Eigen::Matrix3d F = glossa::test::randomDeformationGradient(rng, 0.3);
    const Eigen::Matrix3d Cb = std::pow(F.determinant(), -2.0 / 3.0) * F.transpose() * F;
    const double expected = 0.5 * (Cb.trace() * Cb.trace() - (Cb * Cb).trace());
    const auto I2 = glossa::materials::isochoricI2(F);
    EXPECT_NEAR(I2.value, expected, 1e-13 * expected);
    const double h = 1e-6;
    for (int k = 0; k < 3; ++k)
      for (int L = 0; L < 3; ++L) {
        Eigen::Matrix3d Fp = F, Fm = F;
        Fp(k, L) += h;
        Fm(k, L) -= h;
        const auto p = glossa::materials::isochoricI2(Fp), m = glossa::materials::isochoricI2(Fm);
        EXPECT_NEAR((p.value - m.value) / (2 * h), I2.dF(k, L), 1e-7);
        const Eigen::Matrix3d d2 = (p.dF - m.dF) / (2 * h);
        for (int i = 0; i < 3; ++i)
          for (int J = 0; J < 3; ++J) EXPECT_NEAR(d2(i, J), I2.d2F(i * 3 + J, k * 3 + L), 1e-6);
      }
  }
}

TEST(MooneyRivlin, TwoParameterConformance) { glossa::test::expectConformance(MooneyRivlin(twoParameter(1.0, 10.0)), 31u); }
TEST(MooneyRivlin, FiveParameterConformance) { glossa::test::expectConformance(MooneyRivlin(fiveParameter()), 32u); }
TEST(MooneyRivlin, ArtisynthTongueConformance) { glossa::test::expectConformance(MooneyRivlin::artisynthTongue(), 33u); }
TEST(Yeoh, Conformance) { glossa::test::expectConformance(Yeoh(500.0, -40.0, 12.0), 34u); }

// Incompressible uniaxial stretch F = diag(l, l^-1/2, l^-1/2):
// sigma_11 - sigma_22 = 2 (l^2 - 1/l) (W1 + W2 / l), I1 = l^2 + 2/l, I2 = 2 l + 1/l^2.
TEST(MooneyRivlin, UniaxialIncompressibleStressDifference) {
  for (const auto &c : {twoParameter(1.0, 10.0), fiveParameter()}) {
    const MooneyRivlin m(c);
    for (double l : {0.5, 0.8, 1.2, 1.7, 2.5}) {
      Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
      F(0, 0) = l;
      F(1, 1) = F(2, 2) = 1.0 / std::sqrt(l);
      const Eigen::Matrix3d sigma = m.evaluate(F).P * F.transpose();
      const Partials W = partials(c, l * l + 2.0 / l, 2.0 * l + 1.0 / (l * l));
      const double expected = 2.0 * (l * l - 1.0 / l) * (W.W1 + W.W2 / l);
      EXPECT_NEAR(sigma(0, 0) - sigma(1, 1), expected, 1e-11 * std::abs(expected)) << l;
      EXPECT_NEAR(sigma(1, 1) - sigma(2, 2), 0.0, 1e-11 * std::abs(expected));
      EXPECT_NEAR(sigma.trace(), 0.0, 1e-10 * std::abs(expected)); // deviatoric
    }
  }
}

// Simple shear F = 1 + g e1 (x) e2 (I1 = I2 = 3 + g^2): sigma_12 = 2 g (W1 + W2),
// sigma_11 - sigma_33 = 2 g^2 W1, sigma_22 - sigma_33 = -2 g^2 W2 (Rivlin's universal relations).
TEST(MooneyRivlin, SimpleShearClosedForm) {
  for (const auto &c : {twoParameter(1.0, 10.0), fiveParameter()}) {
    const MooneyRivlin m(c);
    for (double g : {0.05, 0.3, 1.0, 2.0}) {
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      F(0, 1) = g;
      const Eigen::Matrix3d sigma = m.evaluate(F).P * F.transpose();
      const Partials W = partials(c, 3.0 + g * g, 3.0 + g * g);
      const double scale = 2.0 * g * (W.W1 + W.W2);
      EXPECT_NEAR(sigma(0, 1), scale, 1e-11 * scale) << g;
      EXPECT_NEAR(sigma(0, 0) - sigma(2, 2), 2.0 * g * g * W.W1, 1e-11 * scale) << g;
      EXPECT_NEAR(sigma(1, 1) - sigma(2, 2), -2.0 * g * g * W.W2, 1e-11 * scale) << g;
    }
  }
  EXPECT_DOUBLE_EQ(MooneyRivlin(fiveParameter()).shearModulus(), 2.0 * (1037.0 + 250.0));
}

// Yeoh in simple shear: sigma_12 = 2 g psi'(I1), psi' = C10 + 2 C20 a + 3 C30 a^2, a = g^2.
TEST(Yeoh, SimpleShearClosedForm) {
  const Yeoh m(500.0, -40.0, 12.0);
  for (double g : {0.1, 0.7, 1.5}) {
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    F(0, 1) = g;
    const double a = g * g;
    const double expected = 2.0 * g * (500.0 - 80.0 * a + 36.0 * a * a);
    EXPECT_NEAR((m.evaluate(F).P * F.transpose())(0, 1), expected, 1e-11 * std::abs(expected)) << g;
  }
  EXPECT_DOUBLE_EQ(m.shearModulus(), 1000.0);
}

// mi03 at the point: with F = diag(0.2, s, s) the lateral faces are free where
// d/ds [psi_iso(F) + U(J)] = 0, J = 0.2 s^2. Solved by Newton on the law's own stress
// (P_22 of the isochoric part plus U'(J) J / s, the lateral first Piola stress).
TEST(MooneyRivlin, FebioMi03LateralStretch) {
  const MooneyRivlin m(twoParameter(1.0, 10.0));
  const VolumetricEnergy U(VolumetricEnergy::Form::LogSquared, 100.0);
  const double l = 0.2;
  auto lateralStress = [&](double s) {
    const Eigen::Matrix3d F = Eigen::Vector3d(l, s, s).asDiagonal();
    const double J = l * s * s;
    return m.evaluate(F).P(1, 1) + U.dU(J) * J / s;
  };
  double s = 1.0;
  for (int k = 0; k < 50; ++k) {
    const double h = 1e-7, f = lateralStress(s);
    s -= f / ((lateralStress(s + h) - lateralStress(s - h)) / (2 * h));
  }
  EXPECT_NEAR(lateralStress(s), 0.0, 1e-10);
  EXPECT_NEAR(s, 1.416623835, 1e-6);
  EXPECT_NEAR(l * s * s, 0.40136462, 1e-6);
}

TEST(MooneyRivlin, RejectsInvalidParameters) {
  EXPECT_THROW(MooneyRivlin(twoParameter(0.0, 0.0)), std::invalid_argument);
  EXPECT_THROW(MooneyRivlin(twoParameter(1.0, -2.0)), std::invalid_argument);
  EXPECT_THROW(MooneyRivlin(twoParameter(NAN, 1.0)), std::invalid_argument);
  EXPECT_THROW(Yeoh(0.0, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(Yeoh(1.0, INFINITY, 1.0), std::invalid_argument);
}
