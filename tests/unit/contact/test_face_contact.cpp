#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "ContactTestSurfaces.hpp"
#include "FaceContactChecks.hpp"
#include "contact/CylinderObstacle.hpp"
#include "contact/FaceContact.hpp"
#include "contact/PlaneObstacle.hpp"
#include "contact/SphereObstacle.hpp"
#include "contact/TriangulatedObstacle.hpp"

using namespace glossa::contact;
using namespace glossa::contact::test;
using glossa::loads::FaceForces;
using glossa::loads::FaceNodes;
using glossa::loads::FaceTangent;

namespace {

constexpr ContactQuadrature kRules[] = {ContactQuadrature::gauss, ContactQuadrature::nodal};
const char *name(ContactQuadrature rule) { return rule == ContactQuadrature::gauss ? "gauss" : "nodal"; }

// Random warped faces near z = 0 or 0.2 below pressed into `obstacle` with random multipliers in
// [0, lambdaMax], both rules; fails unless the samples exercise faces with every point active
// and faces with a mixed active set.
void checkTangents(const Obstacle &obstacle, double lambdaMax, const std::string &what) {
  for (ContactQuadrature rule : kRules) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> multiplier(0.0, lambdaMax);
    const ContactSettings settings{2.0e5, 1.0, rule, {}};
    int allActive = 0, mixed = 0;
    for (int sample = 0; sample < 40; ++sample) {
      // Every other face pressed 0.2 deeper, so that both full and partial contact occur.
      const FaceNodes X = perturbed(rectangle(1.0, 1.0), rng, 0.15);
      const FaceNodes u = perturbed(uniform(Eigen::Vector3d(0, 0, sample % 2 ? -0.2 : 0.0)), rng, 0.1);
      const FaceMultipliers lambda{multiplier(rng), multiplier(rng), multiplier(rng), multiplier(rng)};
      FaceContactPoints points;
      faceContactForces(obstacle, X, u, lambda, settings, &points);
      // max(0, .) has no derivative at its kink: a point within a step's reach of it is skipped.
      bool nearKink = false;
      for (std::size_t q = 0; q < 4; ++q)
        nearKink = nearKink || std::abs(lambda[q] - settings.penalty * points[q].gap) < 1e-3 * settings.penalty;
      if (nearKink) continue;
      const std::string where = what + " " + name(rule) + " sample " + std::to_string(sample);
      const int active = expectTangentMatchesCentralDifferences(obstacle, X, u, lambda, settings, where);
      allActive += active == 4;
      mixed += active > 0 && active < 4;
    }
    EXPECT_GE(allActive, 3) << what << " " << name(rule);
    EXPECT_GE(mixed, 3) << what << " " << name(rule);
  }
}

}  // namespace

// The tangent includes the variation of the gap, the area and the active set: a tilted plane
// (dNormal = 0), pure penalty and augmented multipliers.
TEST(FaceContact, TangentOnAPlaneMatchesCentralDifferences) {
  const PlaneObstacle plane(Eigen::Vector3d(0.1, 0.2, 0.0), Eigen::Vector3d(0.2, -0.1, 1.0));
  checkTangents(plane, 0.0, "plane, penalty");
  checkTangents(plane, 2.0e4, "plane, multipliers");
}

// ... and of the normal: a sphere of radius 2 under the face's centre, touching z = 0 from
// below, and a spherical cavity of radius 2 touching z = 0 from above (the body inside).
TEST(FaceContact, TangentOnASphereMatchesCentralDifferences) {
  checkTangents(SphereObstacle(Eigen::Vector3d(0.5, 0.5, -2.0), 2.0), 1.0e4, "sphere");
  checkTangents(SphereObstacle(Eigen::Vector3d(0.5, 0.5, 2.0), 2.0, BodySide::inside), 1.0e4, "cavity");
}

// ... and a cylinder of radius 1.5 with an oblique horizontal axis, touching z = 0 from below.
TEST(FaceContact, TangentOnACylinderMatchesCentralDifferences) {
  checkTangents(CylinderObstacle(Eigen::Vector3d(0.5, 0.5, -1.5), Eigen::Vector3d(1.0, 0.3, 0.0), 1.5), 1.0e4,
                "cylinder");
}

// ... and of a triangulated sphere's smoothed normals, whose gap's gradient is not the normal
// (contact/SmoothedProjection.hpp): radius 2 cut into 8 x 16 x 16 triangles, touching z = 0
// from below.
TEST(FaceContact, TangentOnSmoothedNormalsMatchesCentralDifferences) {
  const TriangulatedObstacle sphere(glossa::contact::testing::triangulatedSphere(16, 2.0, {0.5, 0.5, -2.0}),
                                    NormalField::smoothed);
  checkTangents(sphere, 1.0e4, "smoothed triangulated sphere");
}

// A flat 2 x 1.5 face pushed delta = 0.01 into the plane z = 0, pure penalty: every point has
// gap -delta and pressure eps delta; the total force is eps delta A along +z, a quarter at each
// node of the rectangle. Stretched 10 % along x as it is pushed, it carries eps delta times its
// DEFORMED area (the pressure is a force per current area). Both rules.
TEST(FaceContact, FlatFaceInAPlaneCarriesPenaltyTimesDepthTimesArea) {
  const PlaneObstacle plane(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1));
  const double eps = 1.0e6, delta = 0.01;
  const FaceNodes X = rectangle(2.0, 1.5);
  for (ContactQuadrature rule : kRules) {
    const ContactSettings settings{eps, 0.1, rule, {}};
    FaceContactPoints points;
    const FaceForces f = faceContactForces(plane, X, uniform(Eigen::Vector3d(0, 0, -delta)), {0, 0, 0, 0},
                                           settings, &points);
    for (const ContactPointState &p : points) {
      EXPECT_NEAR(p.gap, -delta, 1e-16) << name(rule);
      EXPECT_NEAR(p.pressure, eps * delta, 1e-9) << name(rule);
    }
    EXPECT_TRUE(total(f).isApprox(Eigen::Vector3d(0, 0, eps * delta * 3.0), 1e-14)) << name(rule);
    for (int a = 0; a < 4; ++a)
      EXPECT_TRUE(f.segment<3>(3 * a).isApprox(Eigen::Vector3d(0, 0, eps * delta * 0.75), 1e-14)) << name(rule);

    FaceNodes u = uniform(Eigen::Vector3d(0, 0, -delta));
    u.col(0) += 0.1 * X.col(0);
    EXPECT_NEAR(total(faceContactForces(plane, X, u, {0, 0, 0, 0}, settings))(2), eps * delta * 2.2 * 1.5,
                1e-9 * eps * delta);
  }
}

// The two rules on a trapezoid (0,0), (2,0), (1.5,1), (0.5,1) pushed uniformly into a plane
// (from below, the obstacle above): its area element is j = (3 - t)/8, so a uniform pressure p
// has the consistent nodal forces int N_a p da = p (5/12, 5/12, 1/3, 1/3), what a uniform
// stress in the body balances. The Gauss rule gives exactly those; the nodal rule gives
// p j(node) = p (1/2, 1/2, 1/4, 1/4): the same total 1.5 p, but not what a uniform stress
// balances, so on distorted faces only the Gauss rule passes the patch test with a uniform gap.
TEST(FaceContact, GaussRuleGivesTheConsistentNodalForcesOfAUniformPressure) {
  FaceNodes X;
  X << 0, 0, 0, 2, 0, 0, 1.5, 1, 0, 0.5, 1, 0;
  const PlaneObstacle above(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, -1));
  const double eps = 1.0e5, delta = 0.002, p = eps * delta;
  const FaceNodes u = uniform(Eigen::Vector3d(0, 0, delta));
  const FaceForces gauss = faceContactForces(above, X, u, {0, 0, 0, 0}, {eps, 0.1, ContactQuadrature::gauss, {}});
  const FaceForces nodal = faceContactForces(above, X, u, {0, 0, 0, 0}, {eps, 0.1, ContactQuadrature::nodal, {}});
  const double consistent[4] = {5.0 / 12, 5.0 / 12, 1.0 / 3, 1.0 / 3}, lumped[4] = {0.5, 0.5, 0.25, 0.25};
  for (int a = 0; a < 4; ++a) {
    EXPECT_TRUE(gauss.segment<3>(3 * a).isApprox(Eigen::Vector3d(0, 0, -p * consistent[a]), 1e-14)) << a;
    EXPECT_TRUE(nodal.segment<3>(3 * a).isApprox(Eigen::Vector3d(0, 0, -p * lumped[a]), 1e-14)) << a;
  }
  EXPECT_NEAR(total(gauss)(2), -1.5 * p, 1e-12 * p);
  EXPECT_NEAR(total(nodal)(2), -1.5 * p, 1e-12 * p);
}

// Augmented Lagrangian: a face touching the plane exactly (g = 0) carries its multiplier L
// everywhere, L A in total, and a point with a multiplier held across a gap g carries L - eps g.
TEST(FaceContact, MultiplierIsThePressureAtZeroGap) {
  const PlaneObstacle plane(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1));
  const double L = 3.0e3, eps = 1.0e6;
  for (ContactQuadrature rule : kRules) {
    const ContactSettings settings{eps, 0.1, rule, {}};
    FaceContactPoints points;
    const FaceForces f = faceContactForces(plane, rectangle(2.0, 1.5), FaceNodes::Zero(), {L, L, L, L}, settings,
                                           &points);
    EXPECT_TRUE(total(f).isApprox(Eigen::Vector3d(0, 0, L * 3.0), 1e-14)) << name(rule);
    for (const ContactPointState &p : points) {
      EXPECT_DOUBLE_EQ(p.pressure, L);
      EXPECT_EQ(gapError(p), 0.0);
    }
    faceContactForces(plane, rectangle(2.0, 1.5), uniform(Eigen::Vector3d(0, 0, 1e-3)), {L, L, L, L}, settings,
                      &points);
    EXPECT_NEAR(points[0].pressure, L - eps * 1e-3, 1e-9);
    EXPECT_NEAR(gapError(points[0]), 1e-3, 1e-15);
  }
}

// Clear of the plane with no multiplier, or beyond the search radius: nothing, and the gap of a
// point the search did not reach is +infinity.
TEST(FaceContact, FaceClearOfTheObstacleCarriesNothing) {
  const PlaneObstacle plane(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1));
  const ContactSettings settings{1.0e6, 0.5, ContactQuadrature::gauss, {}};
  FaceContactPoints points;
  FaceTangent K;
  const FaceForces f = faceContactForces(plane, rectangle(1, 1), uniform(Eigen::Vector3d(0, 0, 0.1)),
                                         {0, 0, 0, 0}, settings, &points, &K);
  EXPECT_EQ(f.norm(), 0.0);
  EXPECT_EQ(K.norm(), 0.0);
  EXPECT_DOUBLE_EQ(points[2].gap, 0.1);
  EXPECT_FALSE(points[2].active());
  faceContactForces(plane, rectangle(1, 1), uniform(Eigen::Vector3d(0, 0, 0.6)), {1e3, 1e3, 1e3, 1e3}, settings,
                    &points);
  EXPECT_EQ(points[1].gap, std::numeric_limits<double>::infinity());
  EXPECT_EQ(points[1].pressure, 0.0);
}

// A face resting on the plane at zero gap without multipliers carries nothing, and its tangent
// is the one-sided derivative from the contact side: pushing node b by h into the plane gives
// f = -K e_b h to first order (exactly here: the penalty force is linear in the depth).
TEST(FaceContact, RestingFaceHasTheContactSidesTangent) {
  const PlaneObstacle plane(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1));
  for (ContactQuadrature rule : kRules) {
    const ContactSettings settings{1.0e6, 0.1, rule, {}};
    FaceTangent K;
    const FaceForces f0 = faceContactForces(plane, rectangle(2.0, 1.5), FaceNodes::Zero(), {0, 0, 0, 0}, settings,
                                            nullptr, &K);
    EXPECT_EQ(f0.norm(), 0.0);
    const double h = 1e-7;
    for (int b = 0; b < 4; ++b) {
      FaceNodes u = FaceNodes::Zero();
      u(b, 2) = -h;
      const FaceForces f = faceContactForces(plane, rectangle(2.0, 1.5), u, {0, 0, 0, 0}, settings);
      EXPECT_GT(f.norm(), 0.0);
      EXPECT_LT((f + K.col(3 * b + 2) * h).norm(), 1e-6 * f.norm()) << name(rule) << " node " << b;
    }
  }
}

// The Uzawa update max(0, lambda - eps g) by hand, and the gap error of active points only.
TEST(FaceContact, UzawaUpdateAndGapErrorByHand) {
  EXPECT_DOUBLE_EQ(updatedMultiplier(10.0, 100.0, -0.05), 15.0);
  EXPECT_DOUBLE_EQ(updatedMultiplier(10.0, 100.0, 0.04), 6.0);
  EXPECT_DOUBLE_EQ(updatedMultiplier(10.0, 100.0, 0.2), 0.0);
  EXPECT_DOUBLE_EQ(updatedMultiplier(10.0, 100.0, std::numeric_limits<double>::infinity()), 0.0);
  EXPECT_DOUBLE_EQ(gapError({-0.01, 5.0}), 0.01);
  EXPECT_DOUBLE_EQ(gapError({0.02, 5.0}), 0.02);
  EXPECT_DOUBLE_EQ(gapError({0.3, 0.0}), 0.0);
}

// A rigid flat face (one unknown, its height w) pushed onto a plane by a force F: Newton on the
// kernel's force and tangent finds the penalty solution w = -F/(eps A); one Uzawa update then
// makes lambda = F/A, and the next solve closes the gap (to round-off): the augmented Lagrangian
// enforces g = 0 that the penalty only approaches.
TEST(FaceContact, OneUzawaUpdateClosesTheGapOfARigidFace) {
  const PlaneObstacle plane(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1));
  const double eps = 1.0e5, F = 600.0, A = 3.0;
  const FaceNodes X = rectangle(2.0, 1.5);
  const ContactSettings settings{eps, 1.0, ContactQuadrature::gauss, {}};
  FaceMultipliers lambda{0, 0, 0, 0};
  auto solve = [&] {
    double w = 0.0;
    for (int it = 0; it < 20; ++it) {
      FaceTangent K;
      const double r = total(faceContactForces(plane, X, uniform(Eigen::Vector3d(0, 0, w)), lambda, settings,
                                               nullptr, &K))(2) -
                       F;
      double dr = 0;  // d(total z force)/dw: every node moves by dw along z
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) dr += K(3 * a + 2, 3 * b + 2);
      w -= r / dr;
    }
    return w;
  };
  const double wPenalty = solve();
  EXPECT_NEAR(wPenalty, -F / (eps * A), 1e-15);
  FaceContactPoints points;
  faceContactForces(plane, X, uniform(Eigen::Vector3d(0, 0, wPenalty)), lambda, settings, &points);
  for (std::size_t q = 0; q < 4; ++q) lambda[q] = updatedMultiplier(lambda[q], eps, points[q].gap);
  EXPECT_NEAR(lambda[0], F / A, 1e-9);
  EXPECT_NEAR(solve(), 0.0, 1e-15);
}
