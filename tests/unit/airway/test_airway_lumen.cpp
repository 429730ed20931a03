// The lumen's sections on channels whose cross-sections are known exactly (to
// 1e-10 relative): two parallel planes, a faceted cylinder (its halves the tongue and the wall)
// and a channel tilted out of the axes with a wall wider than the tongue and shifted sideways.
// The centreline and the planes come from the same code as the tongue's. And the closing rule on
// a section whose contact width is known.
#include <gtest/gtest.h>

#include <cmath>

#include "AirwayTestShapes.hpp"
#include "airway/AirwayLumen.hpp"

using namespace glossa::airway;

namespace {
CentrelineSettings along(const Eigen::Vector3d &start, const Eigen::Vector3d &end, int sections) {
  CentrelineSettings c;
  c.start = start;
  c.end = end;
  c.sections = sections;
  return c;
}
}  // namespace

TEST(AirwayLumen, ParallelPlanesGiveGapTimesTheNarrowerWidth) {
  // Tongue z = 0 over y in [-0.02, 0.02]; wall z = 0.006 over y in [-0.03, 0.03]: 6 mm x 40 mm.
  const TriangleSet tongue = test::strip({0, 0, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0.05, -0.02, 0.02);
  const TriangleSet wall = test::strip({0, 0, 0.006}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0.05, -0.03, 0.03, 7, 9);
  const AirwayLumen lumen(tongue, wall, along({0.005, 0, 0}, {0.045, 0, 0}, 7), {});
  const LumenState s = lumen.measure(tongue.vertices);
  ASSERT_EQ(s.sections.size(), 7u);
  const double exact = 0.006 * 0.04;
  for (std::size_t k = 0; k < s.sections.size(); ++k) {
    ASSERT_TRUE(s.sections[k].measured);
    EXPECT_NEAR(s.sections[k].area(), exact, 1e-10 * exact) << "section " << k;
    EXPECT_NEAR(lumen.centreline().planes[k].normal.x(), 1.0, 1e-14);
    EXPECT_NEAR(lumen.centreline().planes[k].origin.z(), 0.003, 1e-15);
    EXPECT_NEAR(lumen.centreline().arcLength[k], 0.04 / 7 * static_cast<double>(k), 1e-15);
  }
  EXPECT_FALSE(s.closed());
  // The tongue pressed flat onto the wall: every section touches across its width and closes.
  std::vector<Eigen::Vector3d> lifted = tongue.vertices;
  for (auto &x : lifted) x.z() = 0.006;
  const LumenState shut = lumen.measure(lifted);
  EXPECT_EQ(shut.closedSections, 7);
  EXPECT_EQ(shut.sections[3].area(), 0.0);
  EXPECT_TRUE(shut.sections[3].lumen.touchesAcross());
  EXPECT_NEAR(shut.sections[3].lumen.contactFraction(), 1.0, 1e-14);
}

TEST(AirwayLumen, CylinderGivesItsInscribedPolygon) {
  // Radius 7 mm, 24 facets: the lower half is the tongue, the upper the wall; a plane square to
  // the axis cuts the regular 24-gon of area (n/2) r^2 sin(2 pi / n).
  const double r = 0.007;
  const int n = 24;
  const TriangleSet tongue = test::halfCylinder(r, 0.04, n, M_PI);
  const TriangleSet wall = test::halfCylinder(r, 0.04, n, 0.0);
  const AirwayLumen lumen(tongue, wall, along({0.004, 0, -r}, {0.036, 0, -r}, 5), {});
  const LumenState s = lumen.measure(tongue.vertices);
  const double exact = 0.5 * n * r * r * std::sin(2.0 * M_PI / n);
  for (const auto &section : s.sections) {
    ASSERT_TRUE(section.measured);
    EXPECT_NEAR(section.area(), exact, 1e-10 * exact);
  }
  // And the polygon tends to the circle: within 1.2 % at 24 facets (1 - sin(2 pi/n) n / (2 pi)).
  EXPECT_NEAR(s.sections[2].area() / (M_PI * r * r), 1.0, 0.012);
}

TEST(AirwayLumen, TiltedChannelWithShiftedWiderWall) {
  // The channel runs along d = (cos a, 0, sin a), a = 35 deg; the tongue's plane contains d and
  // y, the wall is h = 4 mm above it along m = (-sin a, 0, cos a), 50 mm wide and shifted 8 mm
  // in y: the common width is [-0.015, 0.017] ∩ [-0.017, 0.033] = 32 mm.
  const double a = 35.0 * M_PI / 180.0, h = 0.004;
  const Eigen::Vector3d d(std::cos(a), 0, std::sin(a)), m(-std::sin(a), 0, std::cos(a)), y = Eigen::Vector3d::UnitY();
  const TriangleSet tongue = test::strip(Eigen::Vector3d::Zero(), d, y, 0.06, -0.015, 0.017, 9, 7);
  const TriangleSet wall = test::strip(h * m, d, y, 0.06, -0.017, 0.033, 5, 11);
  const AirwayLumen lumen(tongue, wall, along(0.01 * d, 0.05 * d, 6), {});
  const LumenState s = lumen.measure(tongue.vertices);
  const double exact = h * 0.032;
  for (std::size_t k = 0; k < s.sections.size(); ++k) {
    ASSERT_TRUE(s.sections[k].measured);
    EXPECT_NEAR(s.sections[k].area(), exact, 1e-10 * exact);
    EXPECT_NEAR(lumen.centreline().planes[k].normal.dot(d), 1.0, 1e-14);
  }
  // Tilting the tongue about d by lifting one side: the gap is linear across the width and the
  // area is its mean times the width; lift the right edge 4 mm and the section closes along it.
  std::vector<Eigen::Vector3d> tilted = tongue.vertices;
  for (auto &x : tilted) x += h * (x.dot(y) + 0.015) / 0.032 * m;
  const LumenState t = lumen.measure(tilted);
  for (const auto &section : t.sections) EXPECT_NEAR(section.area(), 0.5 * exact, 1e-10 * exact);
  // The smallest area and the closing threshold: at 1 mm^2 (the default) none closes, at
  // 65 mm^2 (above 64) all do.
  EXPECT_EQ(t.closedSections, 0);
  const AirwayLumen strict(tongue, wall, along(0.01 * d, 0.05 * d, 6), {65e-6, 1e-5});
  EXPECT_EQ(strict.measure(tilted).closedSections, 6);
}

TEST(AirwayLumen, ClosesWhenContactSpansTheClosingWidthFraction) {
  // A flat tongue 20 mm wide; the wall lies on it over |u| <= 3 mm, rises with slope 1 to 2 mm
  // above it at |u| = 5 mm and stays there to the sides: a lumen open at both sides (24 mm^2)
  // with contact over 6 mm, 0.3 of the width; within a contact gap of 0.5 mm, over 7 mm (0.35).
  using V = Eigen::Vector2d;
  const std::vector<V> tongue{V(-0.01, 0), V(0.01, 0)};
  const std::vector<V> wall{V(-0.01, 0.002), V(-0.005, 0.002), V(-0.003, 0), V(0.003, 0),
                            V(0.005, 0.002), V(0.01, 0.002)};
  const LumenSection exact = lumenBetween(tongue, false, wall, false, 0.0);
  ASSERT_NEAR(exact.area, 24e-6, 1e-10 * 24e-6);
  ASSERT_NEAR(exact.contactFraction(), 0.3, 1e-12);
  LumenSettings rule{1e-6, 0.0, 1.0};
  EXPECT_FALSE(sectionCloses(exact, rule));  // the default: contact from side to side
  rule.closingWidthFraction = 0.29;
  EXPECT_TRUE(sectionCloses(exact, rule));
  rule.closingWidthFraction = 0.31;
  EXPECT_FALSE(sectionCloses(exact, rule));
  const LumenSection near = lumenBetween(tongue, false, wall, false, 0.0005);
  ASSERT_NEAR(near.contactFraction(), 0.35, 1e-12);
  rule.closingWidthFraction = 0.34;
  EXPECT_TRUE(sectionCloses(near, rule));
  rule.closingWidthFraction = 0.36;
  EXPECT_FALSE(sectionCloses(near, rule));
  // The area rule stands beside it: 24 mm^2 is below a closing area of 25 mm^2.
  EXPECT_TRUE(sectionCloses(exact, LumenSettings{25e-6, 0.0, 1.0}));
}
