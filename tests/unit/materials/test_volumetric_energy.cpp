// VolumetricEnergy::dilatationAtPressure is the inverse of the law's pressure U'(theta): checked
// by putting the dilatation back into U' for each form, and its two limits.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "materials/VolumetricEnergy.hpp"

using glossa::materials::VolumetricEnergy;

TEST(VolumetricEnergy, DilatationAtPressureInvertsThePressureOfEachForm) {
  const double kappa = 2.5e5;
  for (auto form : {VolumetricEnergy::Form::SimoTaylor, VolumetricEnergy::Form::LogSquared,
                    VolumetricEnergy::Form::Quadratic}) {
    const VolumetricEnergy U(form, kappa);
    for (double p : {-0.4 * kappa, -1e-3 * kappa, 0.0, 2e-2 * kappa, 0.3 * kappa}) {
      const double theta = U.dilatationAtPressure(p);
      EXPECT_GT(theta, 0.0);
      EXPECT_NEAR(U.dU(theta), p, 1e-12 * kappa) << static_cast<int>(form) << " p = " << p;
    }
    EXPECT_DOUBLE_EQ(U.dilatationAtPressure(0.0), 1.0);
  }
}

TEST(VolumetricEnergy, DilatationAtPressureLimits) {
  // Exact incompressibility: every pressure at theta = 1.
  const VolumetricEnergy rigid(VolumetricEnergy::Form::SimoTaylor, std::numeric_limits<double>::infinity());
  EXPECT_EQ(rigid.dilatationAtPressure(-3e6), 1.0);
  EXPECT_EQ(rigid.dilatationAtPressure(4e6), 1.0);
  // kappa ln(theta) / theta peaks at kappa / e (theta = e): no dilatation carries more.
  const VolumetricEnergy log(VolumetricEnergy::Form::LogSquared, 1e5);
  EXPECT_DOUBLE_EQ(log.dilatationAtPressure(0.5e5), std::exp(1.0));
  EXPECT_NEAR(log.dU(log.dilatationAtPressure(0.99e5 / std::exp(1.0))), 0.99e5 / std::exp(1.0), 1e-6);
}
