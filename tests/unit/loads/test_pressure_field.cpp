#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "loads/FollowerPressure.hpp"
#include "loads/PressureField.hpp"

using glossa::loads::BreathingProfile;
using glossa::loads::FaceNodes;
using glossa::loads::PressureField;

namespace {
using Rect = BreathingProfile::Rectification;
// Hand values (python: math.sin, **): 2^-0.875 = sin(pi/4)^1.75, (sqrt(3)/2)^1.75,
// sin(2 pi 0.2 / 2.5)^1.75 and |sin(2 pi 1.6 / 2.5)|^1.75.
constexpr double kSinQuarterPi = 0.5452538663326288;
constexpr double kSinThirdPi = 0.777460987221058;
constexpr double kAt0p2 = 0.27857607308636495;
constexpr double kAbsAt1p6 = 0.6336729781458712;
}  // namespace

// Eq. 27 with omega = 2 pi / 2.5 s and exponent 1.75 at hand-computed times.
TEST(BreathingProfile, Eq27HandValues) {
  const BreathingProfile half;  // paper defaults, half-wave
  const BreathingProfile full{2.5, 1.75, 0.0, Rect::FullWave};
  EXPECT_NO_THROW(half.validate());
  EXPECT_EQ(half(0.0), 0.0);
  EXPECT_NEAR(half(2.5 / 4), 1.0, 1e-15);            // peak a quarter period in
  EXPECT_NEAR(half(2.5 / 8), kSinQuarterPi, 1e-14);  // sin(pi/4)^1.75
  EXPECT_NEAR(half(2.5 / 6), kSinThirdPi, 1e-14);    // sin(pi/3)^1.75
  EXPECT_NEAR(half(0.2), kAt0p2, 1e-14);
  EXPECT_NEAR(half(2.5 / 2), 0.0, 1e-20);  // end of the hump (sin ~ 1e-16)
  EXPECT_EQ(half(1.6), 0.0);               // second half period: no load
  EXPECT_EQ(half(3 * 2.5 / 4), 0.0);
  EXPECT_NEAR(half(2.5 + 2.5 / 8), kSinQuarterPi, 1e-13);  // second breath
  EXPECT_NEAR(full(1.6), kAbsAt1p6, 1e-14);                // full wave: a hump every 1.25 s
  EXPECT_NEAR(full(3 * 2.5 / 4), 1.0, 1e-14);
  EXPECT_NEAR(full(0.2), kAt0p2, 1e-14);
}

// Real, finite and in [0, 1] everywhere (the printed sin^1.75 is NaN where sin < 0), and zero
// before the start time; a start time shifts the profile.
TEST(BreathingProfile, RealNonNegativeAndShiftable) {
  for (Rect r : {Rect::HalfWave, Rect::FullWave}) {
    const BreathingProfile b{2.5, 1.75, 0.0, r};
    for (int i = -100; i <= 4000; ++i) {
      const double t = 0.0025 * i, v = b(t);
      ASSERT_TRUE(std::isfinite(v)) << t;
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, 1.0);
      if (t < 0.0) {
        EXPECT_EQ(v, 0.0);
      }
    }
  }
  const BreathingProfile shifted{2.5, 1.75, 0.5, Rect::HalfWave};
  EXPECT_EQ(shifted(0.4), 0.0);
  EXPECT_NEAR(shifted(0.5 + 2.5 / 8), kSinQuarterPi, 1e-14);
  EXPECT_THROW((BreathingProfile{0.0, 1.75, 0.0, Rect::HalfWave}.validate()), std::invalid_argument);
  EXPECT_THROW((BreathingProfile{2.5, -1.0, 0.0, Rect::HalfWave}.validate()), std::invalid_argument);
  EXPECT_THROW((BreathingProfile{2.5, 1.75, NAN, Rect::HalfWave}.validate()), std::invalid_argument);
}

// The §8.3 linear profile: 0 at P_A, 1 at P_P, constant across, clamped beyond the ends.
TEST(PressureField, LinearProfileHandValues) {
  const PressureField axis = PressureField::linear(-500.0, {0, 0, 0}, {2, 0, 0});
  EXPECT_EQ(axis.spatialFactor({0, 0, 0}), 0.0);
  EXPECT_EQ(axis.spatialFactor({2, 0, 0}), 1.0);
  EXPECT_NEAR(axis.spatialFactor({1, 5, -3}), 0.5, 1e-15);  // transverse offset does not matter
  EXPECT_NEAR(axis.spatialFactor({0.5, -1, 7}), 0.25, 1e-15);
  EXPECT_EQ(axis.spatialFactor({-1, 0, 0}), 0.0);
  EXPECT_EQ(axis.spatialFactor({3, 0, 0}), 1.0);
  EXPECT_NEAR(axis({1.5, 0, 0}, 7.0), -375.0, 1e-12);  // constant time factor

  // A tilted axis: d = (1, 2, 2), |d|^2 = 9; X - P_A = (1, 1, 0) projects to 3/9.
  const PressureField tilted = PressureField::linear(900.0, {1, 1, 1}, {2, 3, 3});
  EXPECT_NEAR(tilted.spatialFactor({2, 2, 1}), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(tilted({2, 2, 1}, 0.0), 300.0, 1e-12);

  EXPECT_THROW(PressureField::linear(1.0, {1, 2, 3}, {1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(PressureField::uniform(NAN), std::invalid_argument);
}

// p(X, t) = p_max s(X) b(t) with the breathing profile, and its values at a face's Gauss points.
TEST(PressureField, SpaceTimeProductAndGaussPoints) {
  const PressureField uniform = PressureField::uniform(5000.0, BreathingProfile{});
  EXPECT_NEAR(uniform({3, -2, 1}, 2.5 / 8), 5000.0 * kSinQuarterPi, 1e-10);
  EXPECT_EQ(uniform({3, -2, 1}, 1.6), 0.0);
  EXPECT_NEAR(uniform.timeFactor(0.2), kAt0p2, 1e-14);

  const PressureField field = PressureField::linear(-350.0, {0, 0, 0}, {4, 0, 0}, BreathingProfile{});
  FaceNodes X;  // the square [1,3] x [0,2] in z = 0: Gauss points at x = 2 -+ 1/sqrt(3)
  X << 1, 0, 0, 3, 0, 0, 3, 2, 0, 1, 2, 0;
  const auto p = field.atGaussPoints(X, 2.5 / 4);  // b = 1
  const auto &st = glossa::loads::followerPressureGaussCoordinates();
  for (std::size_t q = 0; q < 4; ++q) {
    const double x = 2.0 + st[q](0);
    EXPECT_NEAR(p[q], -350.0 * x / 4.0, 1e-11) << q;
  }
}
