// The area between two curves of a section (airway/LumenArea) against areas worked by hand:
// a gap that closes to contact over part of the width, a wall that crosses the tongue, and
// the sides closed at the narrower curve's ends or at lateral walls.
#include <gtest/gtest.h>

#include "airway/LumenArea.hpp"

using glossa::airway::lumenBetween;
using V = Eigen::Vector2d;

TEST(LumenArea, RectangleBetweenFlatCurvesOfDifferentWidths) {
  // Tongue over u in [-1, 2], wall over [-3, 1.5], 0.4 apart: the common width is 2.5.
  const auto s = lumenBetween({V(-1, 0.1), V(0.5, 0.1), V(2, 0.1)}, false, {V(1.5, 0.5), V(-3, 0.5)}, false, 0.0);
  EXPECT_DOUBLE_EQ(s.uLeft, -1.0);
  EXPECT_DOUBLE_EQ(s.uRight, 1.5);
  EXPECT_NEAR(s.area, 0.4 * 2.5, 1e-15);
  EXPECT_EQ(s.contactWidth, 0.0);
  ASSERT_EQ(s.outline.size(), 6u);  // tongue at -1, 0.5, 1.5; wall at 1.5, 0.5, -1
  EXPECT_EQ(s.outline.front(), V(-1, 0.1));
  EXPECT_EQ(s.outline.back(), V(-1, 0.5));
}

TEST(LumenArea, WallTouchingAcrossTheMiddle) {
  // The wall comes down onto the flat tongue over u in [-0.5, 0.5]: two triangles of area 1/4.
  const auto s = lumenBetween({V(-1, 0), V(1, 0)}, false, {V(-1, 1), V(-0.5, 0), V(0.5, 0), V(1, 1)}, false, 0.0);
  EXPECT_NEAR(s.area, 0.5, 1e-15);
  EXPECT_NEAR(s.contactWidth, 1.0, 1e-15);
  EXPECT_NEAR(s.contactFraction(), 0.5, 1e-15);
  EXPECT_NEAR(s.openWidth, 1.0, 1e-15);
  EXPECT_FALSE(s.touchesAcross());
  EXPECT_NEAR(s.largestGap, 1.0, 1e-15);
}

TEST(LumenArea, WallPastTheTongueCountsNoArea) {
  // The wall's V dips 1 below the tongue: the gap 2|u| - 1 counts only where positive.
  const auto s = lumenBetween({V(-1, 0), V(1, 0)}, false, {V(-1, 1), V(0, -1), V(1, 1)}, false, 0.0);
  EXPECT_NEAR(s.area, 0.5, 1e-15);
  EXPECT_NEAR(s.contactWidth, 1.0, 1e-15);
  // A contact gap of 0.5 counts |u| <= 0.75 as touching.
  EXPECT_NEAR(lumenBetween({V(-1, 0), V(1, 0)}, false, {V(-1, 1), V(0, -1), V(1, 1)}, false, 0.5).contactWidth, 1.5,
              1e-15);
}

TEST(LumenArea, UpperEnvelopeOfAFoldedTongueCurve) {
  // The tongue's curve runs out to u = 1 at v = 0 and folds back to u = 0 at v = 0.5: over
  // [0, 1] the upper envelope is the fold, 0.5 (1 - u); the wall is flat at v = 1 over [-1, 1].
  const auto s = lumenBetween({V(-1, 0), V(1, 0), V(0, 0.5)}, false, {V(-1, 1), V(1, 1)}, false, 0.0);
  EXPECT_NEAR(s.area, 1.0 + (1.0 - 0.25), 1e-15);
}

TEST(LumenArea, CurvesSideBySideHaveNoCommonWidth) {
  const auto s = lumenBetween({V(-2, 0), V(-1, 0)}, false, {V(1, 1), V(2, 1)}, false, 0.0);
  EXPECT_FALSE(s.spansWidth());
  EXPECT_EQ(s.area, 0.0);
  EXPECT_TRUE(s.outline.empty());
}

TEST(LumenArea, LateralWallsBoundTheWidth) {
  // The wall of WallTouchingAcrossTheMiddle between walls at u = +-0.75: the gap is 2|u| - 1 for
  // 0.5 <= |u| <= 0.75, two triangles of area 1/16; contact over [-0.5, 0.5], 2/3 of the width.
  const std::vector<V> tongue{V(-1, 0), V(1, 0)}, wall{V(-1, 1), V(-0.5, 0), V(0.5, 0), V(1, 1)};
  const auto s = lumenBetween(tongue, false, wall, false, 0.0, 0.75);
  EXPECT_DOUBLE_EQ(s.uLeft, -0.75);
  EXPECT_DOUBLE_EQ(s.uRight, 0.75);
  EXPECT_NEAR(s.area, 0.125, 1e-15);
  EXPECT_NEAR(s.contactFraction(), 2.0 / 3.0, 1e-15);
  // Walls at the contact's edges leave no open width: touching from side to side.
  const auto shut = lumenBetween(tongue, false, wall, false, 0.0, 0.5);
  EXPECT_EQ(shut.area, 0.0);
  EXPECT_TRUE(shut.touchesAcross());
  // Walls wider than both curves change nothing.
  const auto wide = lumenBetween(tongue, false, wall, false, 0.0, 5.0);
  EXPECT_EQ(wide.area, lumenBetween(tongue, false, wall, false, 0.0).area);
  EXPECT_DOUBLE_EQ(wide.uLeft, -1.0);
}
