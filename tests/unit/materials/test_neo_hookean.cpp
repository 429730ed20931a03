#include <cmath>

#include <gtest/gtest.h>

#include "MaterialConformance.hpp"
#include "materials/NeoHookean.hpp"
#include "materials/VolumetricEnergy.hpp"

using glossa::materials::NeoHookean;
using glossa::materials::VolumetricEnergy;

TEST(NeoHookean, Conformance) { glossa::test::expectConformance(NeoHookean(80.194e6), 1u); }

// Incompressible uniaxial stretch lambda: sigma_11 - sigma_22 = mu (lambda^2 - 1/lambda)
// (the analytic Neo-Hookean law; the hydrostatic part belongs to the element's pressure).
TEST(NeoHookean, UniaxialIncompressibleStressDifference) {
  const double mu = 1.7e3;
  NeoHookean m(mu);
  for (double lambda : {0.6, 0.9, 1.3, 2.0}) {
    Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
    F(0, 0) = lambda;
    F(1, 1) = F(2, 2) = 1.0 / std::sqrt(lambda);
    const Eigen::Matrix3d sigma = m.evaluate(F).P * F.transpose(); // J = 1
    EXPECT_NEAR(sigma(0, 0) - sigma(1, 1), mu * (lambda * lambda - 1.0 / lambda), 1e-9 * mu);
  }
}

TEST(NeoHookean, RejectsNonPositiveModulus) { EXPECT_THROW(NeoHookean(0.0), std::invalid_argument); }

TEST(VolumetricEnergy, DerivativesMatchFiniteDifferences) {
  for (auto form : {VolumetricEnergy::Form::SimoTaylor, VolumetricEnergy::Form::LogSquared,
                    VolumetricEnergy::Form::Quadratic}) {
    VolumetricEnergy U(form, 3.0e5);
    for (double t : {0.7, 0.95, 1.0, 1.2}) {
      const double h = 1e-6;
      EXPECT_NEAR(U.dU(t), (U.energy(t + h) - U.energy(t - h)) / (2 * h), 1e-5 * U.kappa());
      EXPECT_NEAR(U.d2U(t), (U.dU(t + h) - U.dU(t - h)) / (2 * h), 1e-5 * U.kappa());
    }
    // Linearisation at theta = 1: U'' = kappa, U(1) = U'(1) = 0.
    EXPECT_NEAR(U.energy(1.0), 0.0, 1e-12);
    EXPECT_NEAR(U.dU(1.0), 0.0, 1e-9);
    EXPECT_NEAR(U.d2U(1.0), U.kappa(), 1e-9 * U.kappa());
  }
}

TEST(VolumetricEnergy, BulkModulusFromPoissonRatio) {
  // Step-44's numbers: mu = 80.194 MPa, nu = 0.4999 -> kappa = 2 mu (1+nu) / (3 (1-2nu)).
  EXPECT_NEAR(glossa::materials::bulkModulus(80.194e6, 0.4999), 2 * 80.194e6 * 1.4999 / (3 * 0.0002),
              1.0);
  EXPECT_THROW(glossa::materials::bulkModulus(1.0, 0.5), std::invalid_argument);
}
