// The curves where a plane cuts a faceted surface (airway/PlaneCut): an open strip gives one open
// polyline with its ends on the strip's edges, a closed tube a closed loop, and a corner lying on
// the plane does not break the curve.
#include <gtest/gtest.h>

#include "AirwayTestShapes.hpp"
#include "airway/PlaneCut.hpp"

using namespace glossa::airway;

TEST(PlaneCut, StripGivesOneOpenPolylineAcrossIt) {
  const TriangleSet s = test::strip(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1.0,
                                    -0.3, 0.2);
  SectionPlane p;
  p.origin = Eigen::Vector3d(0.33, 0, 0);
  const auto curves = cutSurface(s.vertices, s.triangles, p);
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_FALSE(curves[0].closed);
  const auto &pts = curves[0].points;
  EXPECT_NEAR(std::abs(pts.front().y() - pts.back().y()), 0.5, 1e-15);
  for (const auto &x : pts) EXPECT_NEAR(x.x(), 0.33, 1e-15);
  // Through a row of grid corners (x = 0.5 with 8 cells along x): still one unbroken curve.
  p.origin.x() = 0.5;
  const auto onCorners = cutSurface(s.vertices, s.triangles, p);
  ASSERT_EQ(onCorners.size(), 1u);
  EXPECT_NEAR(std::abs(onCorners[0].points.front().y() - onCorners[0].points.back().y()), 0.5, 1e-15);
}

TEST(PlaneCut, TubeGivesAClosedLoopOfItsFacets) {
  TriangleSet tube = test::halfCylinder(1.0, 1.0, 12, 0.0);
  const TriangleSet other = test::halfCylinder(1.0, 1.0, 12, M_PI);
  // Join the halves into one tube: the other half's vertices after this one's, then merge the two
  // seams by reusing this half's seam vertices.
  const int n = static_cast<int>(tube.vertices.size());
  std::vector<int> map;
  for (std::size_t v = 0; v < other.vertices.size(); ++v) {
    int same = -1;
    for (int w = 0; w < n; ++w)
      if ((tube.vertices[static_cast<std::size_t>(w)] - other.vertices[v]).norm() < 1e-12) same = w;
    if (same < 0) {
      same = static_cast<int>(tube.vertices.size());
      tube.vertices.push_back(other.vertices[v]);
    }
    map.push_back(same);
  }
  for (const auto &t : other.triangles)
    tube.triangles.push_back({map[static_cast<std::size_t>(t[0])], map[static_cast<std::size_t>(t[1])],
                              map[static_cast<std::size_t>(t[2])]});
  SectionPlane p;
  p.origin = Eigen::Vector3d(0.4, 0, 0);
  const auto curves = cutSurface(tube.vertices, tube.triangles, p);
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_TRUE(curves[0].closed);
  // A plane square to the axis between grid rows passes each of the 12 facets' two triangles.
  EXPECT_EQ(curves[0].points.size(), 24u);
  EXPECT_NEAR(curves[0].distanceTo(Eigen::Vector3d(0.4, 0, 0)), std::cos(M_PI / 12), 1e-14);
}

TEST(PlaneCut, NearestCurveOfTwo) {
  TriangleSet a = test::strip(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1, -1, 1);
  const TriangleSet b = test::strip(Eigen::Vector3d(0, 0, 2), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1, -1, 1);
  const int n = static_cast<int>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) a.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  SectionPlane p;
  p.origin = Eigen::Vector3d(0.7, 0, 0);
  const auto curves = cutSurface(a.vertices, a.triangles, p);
  ASSERT_EQ(curves.size(), 2u);
  EXPECT_NEAR(nearestCurve(curves, Eigen::Vector3d(0.7, 0, 1.6))->points.front().z(), 2.0, 1e-15);
  EXPECT_NEAR(nearestCurve(curves, Eigen::Vector3d(0.7, 0, 0.9))->points.front().z(), 0.0, 1e-15);
}
