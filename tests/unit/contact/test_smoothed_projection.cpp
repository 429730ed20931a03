// Smoothed (vertex-interpolated) normals on triangulated surfaces:
//  - on a flat sheet they are the faceted answer;
//  - across an edge the normal turns continuously where the faceted one jumps by the dihedral
//    angle; at an edge's midpoint it is the mean of its vertices' normals;
//  - dNormal and the gap's gradient against central differences, on faces, edges and corners,
//    outside and inside;
//  - on a triangulated sphere, the normal against the sphere's own (x - c)/|x - c|, an
//    independent reference, beside the faceted normal's error.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "ContactTestSurfaces.hpp"
#include "contact/TriangulatedObstacle.hpp"

namespace {

using glossa::contact::ClosestPoint;
using glossa::contact::NormalField;
using glossa::contact::TriangulatedObstacle;
namespace ct = glossa::contact::testing;

ClosestPoint query(const TriangulatedObstacle &o, const Eigen::Vector3d &x) { return ct::queryAnywhere(o, x); }

double angle(const Eigen::Vector3d &a, const Eigen::Vector3d &b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

TEST(SmoothedProjection, OnAFlatSheetItIsTheFacetedAnswer) {
  const TriangulatedObstacle sheet(ct::unitSquareSheet(), NormalField::smoothed);
  const ClosestPoint cp = query(sheet, {0.3, 0.6, 0.2});
  EXPECT_NEAR(cp.gap, 0.2, 1e-15);
  EXPECT_LT((cp.normal - Eigen::Vector3d::UnitZ()).norm(), 1e-15);
  EXPECT_LT(cp.dNormal.norm(), 1e-15);
  EXPECT_LT((cp.gapGradient() - Eigen::Vector3d::UnitZ()).norm(), 1e-15);
  // Beside the free edge the faceted rule stands: apart, at the distance.
  EXPECT_NEAR(query(sheet, {0.5, -0.3, -0.2}).gap, std::sqrt(0.13), 1e-15);
}

// The octahedron's faces x + y + z = 1 and x + y - z = 1 meet at 109.5 degrees along the edge
// from (1, 0, 0) to (0, 1, 0); by symmetry each vertex normal is the vertex's own direction.
TEST(SmoothedProjection, NormalTurnsContinuouslyAcrossAnEdge) {
  const TriangulatedObstacle faceted(ct::octahedron());
  const TriangulatedObstacle smoothed(ct::octahedron(), NormalField::smoothed);
  const double delta = 1e-6;
  // Points 0.01 above the two faces, delta from the edge on either side.
  const Eigen::Vector3d above(1, 1, 1), below(1, 1, -1);
  const Eigen::Vector3d xUp = Eigen::Vector3d(0.6 - delta / 2, 0.4 - delta / 2, delta) + 0.01 * above.normalized();
  const Eigen::Vector3d xDown = Eigen::Vector3d(0.6 - delta / 2, 0.4 - delta / 2, -delta) + 0.01 * below.normalized();
  EXPECT_NEAR(angle(query(faceted, xUp).normal, query(faceted, xDown).normal), std::acos(1.0 / 3.0), 1e-12);
  EXPECT_LT(angle(query(smoothed, xUp).normal, query(smoothed, xDown).normal), 1e-5);
  // On the edge: 0.6 (1, 0, 0) + 0.4 (0, 1, 0), normalised.
  const ClosestPoint onEdge = query(smoothed, Eigen::Vector3d(0.6, 0.4, 0) + 0.01 * Eigen::Vector3d(1, 1, 0).normalized());
  EXPECT_LT((onEdge.normal - Eigen::Vector3d(0.6, 0.4, 0).normalized()).norm(), 1e-15);
  // At a corner the vertex's own normal.
  EXPECT_LT((query(smoothed, {1.3, 0.01, -0.02}).normal - Eigen::Vector3d::UnitX()).norm(), 1e-15);
}

// Random points within 0.3 R of a coarse sphere (96 triangles), outside and inside, land on faces,
// edges and corners of the closest triangle alike.
TEST(SmoothedProjection, DNormalAndGapGradientMatchCentralDifferences) {
  const TriangulatedObstacle sphere(ct::triangulatedSphere(2, 1.0, {0.1, -0.2, 0.3}), NormalField::smoothed);
  std::mt19937 rng(5);
  std::normal_distribution<double> direction(0.0, 1.0);
  std::uniform_real_distribution<double> radius(0.7, 1.3);
  const double h = 1e-6;
  for (int sample = 0; sample < 200; ++sample) {
    const Eigen::Vector3d x =
        Eigen::Vector3d(0.1, -0.2, 0.3) + radius(rng) * Eigen::Vector3d(direction(rng), direction(rng), direction(rng)).normalized();
    const ClosestPoint cp = query(sphere, x);
    const Eigen::Matrix3d dN = ct::centralDifference([&](const Eigen::Vector3d &y) { return query(sphere, y).normal; }, x, h);
    Eigen::Vector3d dG;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(j);
      dG(j) = (query(sphere, x + e).gap - query(sphere, x - e).gap) / (2 * h);
    }
    EXPECT_LT((cp.dNormal - dN).norm(), 1e-7 * (1 + cp.dNormal.norm())) << "sample " << sample << " at " << x.transpose();
    EXPECT_LT((cp.gapGradient() - dG).norm(), 1e-7) << "sample " << sample << " at " << x.transpose();
  }
}

// On a sphere cut into 8 x 16 triangles (edges of about 22 degrees), at points within 5 % of the
// radius: the faceted normal is off the sphere's own by up to about half an edge's angle; the
// smoothed one, interpolated between vertex normals that are the sphere's own by symmetry, by a
// second-order error, several times smaller. The gap, measured from the same faceted closest
// point, keeps the chord's sag either way.
TEST(SmoothedProjection, OnASphereTheNormalFollowsTheSpheresOwn) {
  const Eigen::Vector3d c(0.1, -0.2, 0.3);
  const TriangulatedObstacle faceted(ct::triangulatedSphere(4, 1.0, c));
  const TriangulatedObstacle smoothed(ct::triangulatedSphere(4, 1.0, c), NormalField::smoothed);
  std::mt19937 rng(11);
  std::normal_distribution<double> direction(0.0, 1.0);
  std::uniform_real_distribution<double> radius(0.95, 1.05);
  double worstFaceted = 0, worstSmoothed = 0;
  for (int sample = 0; sample < 2000; ++sample) {
    const Eigen::Vector3d x = c + radius(rng) * Eigen::Vector3d(direction(rng), direction(rng), direction(rng)).normalized();
    const Eigen::Vector3d exact = (x - c).normalized();
    worstFaceted = std::max(worstFaceted, angle(query(faceted, x).normal, exact));
    worstSmoothed = std::max(worstSmoothed, angle(query(smoothed, x).normal, exact));
  }
  std::printf("largest angle to the sphere's normal: faceted %.2f deg, smoothed %.2f deg\n",
              worstFaceted * 180 / M_PI, worstSmoothed * 180 / M_PI);
  EXPECT_GT(worstFaceted, 0.1);  // the facets are coarse: about 6 degrees and more
  EXPECT_LT(worstSmoothed, 0.25 * worstFaceted);
}

}  // namespace
