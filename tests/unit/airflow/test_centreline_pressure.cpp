// The pressure on a face from its position along the centreline: the projection onto a bent
// centreline gives the arc length measured along it by hand; linear interpolation reproduces a
// pressure linear in arc length exactly and is constant beyond the ends; the nearest section
// takes the closer section's pressure.
#include <gtest/gtest.h>

#include <stdexcept>

#include "airflow/CentrelinePressure.hpp"

namespace glossa::airflow {
namespace {

// An L-shaped centreline: 0.04 m along x, then 0.03 m along z; sections at its corners and the
// middle of each leg, so their arc lengths are 0, 0.02, 0.04, 0.055, 0.07.
CentrelinePressure bent() {
  return CentrelinePressure({{0, 0, 0}, {0.02, 0, 0}, {0.04, 0, 0}, {0.04, 0, 0.015}, {0.04, 0, 0.03}},
                            {0.0, 0.02, 0.04, 0.055, 0.07});
}

TEST(CentrelinePressure, ArcLengthIsThatOfTheNearestCentrelinePoint) {
  const CentrelinePressure c = bent();
  EXPECT_NEAR(c.arcLengthOf({0.013, 0.008, -0.004}), 0.013, 1e-15);  // beside the first leg
  EXPECT_NEAR(c.arcLengthOf({0.046, -0.01, 0.021}), 0.061, 1e-15);   // beside the second
  EXPECT_NEAR(c.arcLengthOf({-0.01, 0.0, 0.0}), 0.0, 0.0);           // before the first section
  EXPECT_NEAR(c.arcLengthOf({0.04, 0.0, 0.05}), 0.07, 0.0);          // past the last
  // Inside the bend, 0.004 m from the first leg and 0.003 m from the second (at arc length 0.044): the second is nearer.
  EXPECT_NEAR(c.arcLengthOf({0.037, 0.0, 0.004}), 0.044, 1e-15);
}

TEST(CentrelinePressure, LinearInterpolationIsExactForALinearPressure) {
  const CentrelinePressure c = bent();
  const std::vector<double> p{-10.0, -30.0, -50.0, -65.0, -80.0};  // -10 - 1000 s [Pa]
  for (double s : {0.0, 0.007, 0.02, 0.031, 0.047, 0.07})
    EXPECT_NEAR(c.pressureAtArcLength(s, p, PressureMapping::linear), -10.0 - 1000.0 * s, 1e-12);
  EXPECT_EQ(c.pressureAtArcLength(-0.5, p, PressureMapping::linear), -10.0);
  EXPECT_EQ(c.pressureAtArcLength(0.5, p, PressureMapping::linear), -80.0);
  EXPECT_NEAR(c.pressureAt({0.046, -0.01, 0.021}, p, PressureMapping::linear), -71.0, 1e-12);
}

TEST(CentrelinePressure, NearestSectionTakesTheCloserSectionsPressure) {
  const CentrelinePressure c = bent();
  const std::vector<double> p{1.0, 2.0, 3.0, 4.0, 5.0};
  EXPECT_EQ(c.pressureAtArcLength(0.009, p, PressureMapping::nearestSection), 1.0);
  EXPECT_EQ(c.pressureAtArcLength(0.011, p, PressureMapping::nearestSection), 2.0);
  EXPECT_EQ(c.pressureAtArcLength(0.05, p, PressureMapping::nearestSection), 4.0);
  EXPECT_EQ(c.pressureAt({0.046, -0.01, 0.066}, p, PressureMapping::nearestSection), 5.0);
}

TEST(CentrelinePressure, MismatchedOrUnorderedSectionsAreRefused) {
  EXPECT_THROW(CentrelinePressure({}, {}), std::invalid_argument);
  EXPECT_THROW(CentrelinePressure({{0, 0, 0}, {1, 0, 0}}, {0.0}), std::invalid_argument);
  EXPECT_THROW(CentrelinePressure({{0, 0, 0}, {1, 0, 0}}, {1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(bent().pressureAtArcLength(0.01, {1.0, 2.0}, PressureMapping::linear), std::invalid_argument);
}

}  // namespace
}  // namespace glossa::airflow
