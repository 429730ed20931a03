// The implicit surface of a triangulated obstacle (normal field = implicit):
//  - on a flat sheet it is the exact signed distance, with the sheet's normal;
//  - its gap's gradient and the normal's derivative against central differences, at random
//    points on both sides of a coarse sphere;
//  - where a contact point's foot crosses an edge, the gap's gradient (the contact stiffness)
//    turns continuously: on segments across every edge of a coarse sphere, just inside and just
//    outside it, the gradient changes by no more than its Lipschitz bound per step, where the
//    smoothed normals' gradient turns by the angle between the triangles at once;
//  - on a finer sphere, the gap against the exact distance to the sphere, |x - c| - R: within
//    the smoothing the header predicts, about 0.14 R_s^2 / (2 rho).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "ContactTestSurfaces.hpp"
#include "contact/ImplicitSurface.hpp"
#include "contact/TriangulatedObstacle.hpp"

namespace {

using glossa::contact::ClosestPoint;
using glossa::contact::NormalField;
using glossa::contact::TriangulatedObstacle;
namespace ct = glossa::contact::testing;

ClosestPoint query(const TriangulatedObstacle &o, const Eigen::Vector3d &x) { return ct::queryAnywhere(o, x); }

TEST(ImplicitSurface, OnAFlatSheetItIsTheSignedDistance) {
  const TriangulatedObstacle sheet(ct::unitSquareSheet(), NormalField::implicit, 1.0);
  for (const double z : {0.05, -0.03}) {
    const ClosestPoint cp = query(sheet, {0.4, 0.55, z});
    EXPECT_NEAR(cp.gap, z, 1e-14);
    EXPECT_LT((cp.normal - Eigen::Vector3d::UnitZ()).norm(), 1e-14);
    EXPECT_LT((cp.gapGradient() - Eigen::Vector3d::UnitZ()).norm(), 1e-13);
    EXPECT_LT(cp.dNormal.norm(), 1e-12);
  }
  // Beside the free edge the faceted rule stands: apart, at the distance.
  EXPECT_NEAR(query(sheet, {0.5, -0.3, -0.2}).gap, std::sqrt(0.13), 1e-15);
}

TEST(ImplicitSurface, GapGradientAndDNormalMatchCentralDifferences) {
  const Eigen::Vector3d c(0.1, -0.2, 0.3);
  const TriangulatedObstacle sphere(ct::triangulatedSphere(3, 1.0, c), NormalField::implicit);
  std::mt19937 rng(7);
  std::normal_distribution<double> direction(0.0, 1.0);
  std::uniform_real_distribution<double> radius(0.9, 1.1);
  const double h = 1e-6;
  for (int sample = 0; sample < 200; ++sample) {
    const Eigen::Vector3d x =
        c + radius(rng) * Eigen::Vector3d(direction(rng), direction(rng), direction(rng)).normalized();
    const ClosestPoint cp = query(sphere, x);
    const Eigen::Matrix3d dN =
        ct::centralDifference([&](const Eigen::Vector3d &y) { return query(sphere, y).normal; }, x, h);
    Eigen::Vector3d dG;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(j);
      dG(j) = (query(sphere, x + e).gap - query(sphere, x - e).gap) / (2 * h);
    }
    EXPECT_LT((cp.dNormal - dN).norm(), 1e-7 * (1 + cp.dNormal.norm())) << "sample " << sample;
    EXPECT_LT((cp.gapGradient() - dG).norm(), 1e-8) << "sample " << sample;
  }
}

// The largest change of the gap's gradient per unit length along segments 0.02 long across
// every edge of a 32-triangle sphere at 2 % of the radius inside and outside it.
double largestGradientChangeRate(const TriangulatedObstacle &sphere, const glossa::contact::TriangleSurface &surface,
                                 const Eigen::Vector3d &c) {
  const double step = 1e-5;
  double worst = 0;
  for (std::size_t t = 0; t < surface.numTriangles(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d a = surface.corner(t, k), b = surface.corner(t, (k + 1) % 3);
      const Eigen::Vector3d across = (b - a).cross(0.5 * (a + b) - c).normalized();
      const Eigen::Vector3d onEdge = 0.5 * (a + b) + 0.13 * (b - a);
      for (const double depth : {-0.02, 0.02}) {
        const Eigen::Vector3d centre = c + (1.0 + depth) * (onEdge - c).normalized();
        Eigen::Vector3d previous = query(sphere, centre - 0.01 * across).gapGradient();
        for (int i = 1; i <= 2000; ++i) {
          const Eigen::Vector3d gradient = query(sphere, centre + (-0.01 + i * step) * across).gapGradient();
          worst = std::max(worst, (gradient - previous).norm() / step);
          previous = gradient;
        }
      }
    }
  }
  return worst;
}

TEST(ImplicitSurface, TheContactStiffnessTurnsContinuouslyAcrossEdges) {
  const Eigen::Vector3d c(0.1, -0.2, 0.3);
  const auto surface = ct::triangulatedSphere(2, 1.0, c);
  const TriangulatedObstacle smoothed(ct::triangulatedSphere(2, 1.0, c), NormalField::smoothed);
  const TriangulatedObstacle implicit(ct::triangulatedSphere(2, 1.0, c), NormalField::implicit);
  const double smoothedRate = largestGradientChangeRate(smoothed, surface, c);
  const double implicitRate = largestGradientChangeRate(implicit, surface, c);
  std::printf("largest change of the gap's gradient per unit length across edges: smoothed %.3g, implicit %.3g\n",
              smoothedRate, implicitRate);
  // On the smoothed normals the gradient (about the face normal) jumps within one step of 1e-5
  // where the foot crosses an edge (measured: by 0.094, a rate of 9.4e3).
  EXPECT_GT(smoothedRate, 1e3);
  // The implicit surface's gradient changes at the rate of its Hessian, about the sphere's
  // curvature, 1 (measured: 1.07).
  EXPECT_LT(implicitRate, 3.0);
}

TEST(ImplicitSurface, OnASphereTheGapIsTheDistanceWithinTheSmoothing) {
  const Eigen::Vector3d c(0.1, -0.2, 0.3);
  const auto surface = ct::triangulatedSphere(8, 1.0, c);
  const TriangulatedObstacle sphere(ct::triangulatedSphere(8, 1.0, c), NormalField::implicit);
  const double R = sphere.implicitRadius();
  const double smoothing = 0.14 * R * R / 2.0;  // <r^2> / (2 rho), rho = 1
  std::mt19937 rng(3);
  std::normal_distribution<double> direction(0.0, 1.0);
  std::uniform_real_distribution<double> radius(0.98, 1.02);
  double worstGap = 0, worstAngle = 0;
  for (int sample = 0; sample < 500; ++sample) {
    const Eigen::Vector3d x =
        c + radius(rng) * Eigen::Vector3d(direction(rng), direction(rng), direction(rng)).normalized();
    const ClosestPoint cp = query(sphere, x);
    worstGap = std::max(worstGap, std::abs(cp.gap - ((x - c).norm() - 1.0)));
    const Eigen::Vector3d exact = (x - c).normalized();
    worstAngle = std::max(worstAngle, std::atan2(cp.normal.cross(exact).norm(), cp.normal.dot(exact)));
  }
  std::printf("support radius %.4f; largest gap error %.3g (predicted smoothing %.3g); largest normal angle %.3g deg\n",
              R, worstGap, smoothing, worstAngle * 180 / M_PI);
  EXPECT_LT(worstGap, 2.0 * smoothing);
  EXPECT_LT(worstAngle * 180 / M_PI, 2.0);
}

}  // namespace
