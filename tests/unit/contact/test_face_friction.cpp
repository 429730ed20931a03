// Coulomb friction and tied contact in the face kernel (contact/FrictionLaw through
// contact/FaceContact): the non-symmetric tangent against central differences in stick, in slip
// and tied (in tension too), on a plane, a sphere and a cylinder; the stick and slip forces, the
// return-mapped anchor and the slip of a flat face by hand; a moving plane dragging a sticking face.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "FaceContactChecks.hpp"
#include "contact/CylinderObstacle.hpp"
#include "contact/FaceContact.hpp"
#include "contact/MovingObstacle.hpp"
#include "contact/PlaneObstacle.hpp"
#include "contact/SphereObstacle.hpp"
#include "loads/FaceShape.hpp"

using namespace glossa::contact;
using namespace glossa::contact::test;

namespace {

// The contact points' current positions on face X + u.
std::array<Eigen::Vector3d, 4> contactPoints(const FaceNodes &X, const FaceNodes &u, ContactQuadrature rule) {
  std::array<Eigen::Vector3d, 4> x;
  for (std::size_t q = 0; q < 4; ++q) {
    const auto &s = contactPointCoordinates(rule)[q];
    x[q] = (X + u).transpose() * glossa::loads::faceShape(s(0), s(1)).N;
  }
  return x;
}

enum class Expect { stick, slip };

// Random warped faces pressed into `obstacle` with random multipliers, each contact point anchored
// at a random offset (up to `offset`) from where it is: the tangent against central differences at
// fixed anchors. Samples with a point near the kink of max(0, .) or near the cone |t_T| = mu t_N
// (where the law has no derivative) are skipped; fails unless the samples had points in the
// expected state (stick or slip).
void checkFrictionTangents(const Obstacle &obstacle, double mu, double offset, Expect expect, const std::string &what) {
  for (ContactQuadrature rule : {ContactQuadrature::gauss, ContactQuadrature::nodal}) {
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> multiplier(0.0, 1.0e4), shift(-offset, offset);
    ContactSettings settings{2.0e5, 1.0, rule, {}};
    settings.friction = {FrictionLaw::coulomb, mu, 1.0e5};
    int checked = 0, inState = 0;
    for (int sample = 0; sample < 40; ++sample) {
      const FaceNodes X = perturbed(rectangle(1.0, 1.0), rng, 0.15);
      const FaceNodes u = perturbed(uniform(Eigen::Vector3d(0, 0, -0.1)), rng, 0.05);
      const FaceMultipliers lambda{multiplier(rng), multiplier(rng), multiplier(rng), multiplier(rng)};
      const auto x = contactPoints(X, u, rule);
      FaceAnchors anchors;
      bool nearKink = false;
      int count = 0;
      for (std::size_t q = 0; q < 4; ++q) {
        anchors[q] = obstacle.toBody(x[q] + Eigen::Vector3d(shift(rng), shift(rng), shift(rng)));
        const auto cp = obstacle.closest(x[q], 1.0);
        const double tN = lambda[q] - settings.penalty * (cp ? cp->gap : 1.0);
        const Eigen::Vector3d v = x[q] - obstacle.toWorld(anchors[q]);
        const double size = settings.friction.penalty * (v - cp->normal.dot(v) * cp->normal).norm();
        nearKink = nearKink || std::abs(tN) < 1e-3 * settings.penalty || std::abs(size - mu * tN) < 1e-2 * size;
        if (tN > 0) count += (size > mu * tN) == (expect == Expect::slip);
      }
      if (nearKink) continue;
      expectTangentMatchesCentralDifferences(obstacle, X, u, lambda, settings,
                                             what + " rule " + std::to_string(int(rule)) + " sample " +
                                                 std::to_string(sample),
                                             &anchors);
      ++checked;
      inState += count;
    }
    EXPECT_GE(checked, 10) << what;
    EXPECT_GE(inState, 20) << what;
  }
}

}  // namespace

// Stick (a large mu: every trial traction inside the cone) and slip (mu = 0.3, offsets large
// enough to leave it) on a tilted plane, a sphere and an oblique cylinder (dNormal != 0 enters the
// tangential projection).
TEST(FaceFriction, TangentInStickAndSlipMatchesCentralDifferences) {
  const PlaneObstacle plane(Eigen::Vector3d(0.1, 0.2, 0.0), Eigen::Vector3d(0.2, -0.1, 1.0));
  const SphereObstacle sphere(Eigen::Vector3d(0.5, 0.5, -2.0), 2.0);
  const CylinderObstacle cylinder(Eigen::Vector3d(0.5, 0.5, -1.5), Eigen::Vector3d(1.0, 0.3, 0.0), 1.5);
  for (const auto &[obstacle, name] : {std::pair<const Obstacle *, std::string>{&plane, "plane"},
                                       {&sphere, "sphere"}, {&cylinder, "cylinder"}}) {
    checkFrictionTangents(*obstacle, 50.0, 0.02, Expect::stick, name + " stick");
    checkFrictionTangents(*obstacle, 0.3, 0.3, Expect::slip, name + " slip");
  }
}

// Tied: anchored points, pressed in or pulled 0.05 out of the obstacle (tension), sheared.
TEST(FaceFriction, TiedTangentMatchesCentralDifferencesInTension) {
  const SphereObstacle sphere(Eigen::Vector3d(0.5, 0.5, -2.0), 2.0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> shift(-0.05, 0.05);
  ContactSettings settings{2.0e5, 1.0, ContactQuadrature::gauss, {}};
  settings.friction.law = FrictionLaw::tied;
  for (int sample = 0; sample < 10; ++sample) {
    const FaceNodes X = perturbed(rectangle(1.0, 1.0), rng, 0.15);
    const FaceNodes u = perturbed(uniform(Eigen::Vector3d(0, 0, sample % 2 ? 0.05 : -0.05)), rng, 0.02);
    FaceAnchors anchors;
    const auto x = contactPoints(X, u, settings.rule);
    for (std::size_t q = 0; q < 4; ++q) anchors[q] = sphere.closest(x[q], 1.0)->point + Eigen::Vector3d(shift(rng), shift(rng), 0);
    const int active = expectTangentMatchesCentralDifferences(sphere, X, u, {0, 0, 0, 0}, settings,
                                                              "tied sample " + std::to_string(sample), &anchors);
    EXPECT_EQ(active, 4);
  }
}

// A flat 2 x 1.5 face pushed delta into the plane z = 0 (t_N = eps delta), each point d along x
// from its anchor: within the cone it sticks with t_T = -eps_T d e_x (total -eps_T d A); beyond
// it slips with |t_T| = mu t_N, its anchor follows to mu t_N / eps_T behind it and the slip of the
// increment is d - mu t_N / eps_T.
TEST(FaceFriction, FlatFaceSticksThenSlipsAtMuTimesThePressure) {
  const PlaneObstacle plane(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1));
  const double eps = 1.0e6, epsT = 5.0e5, delta = 0.01, mu = 0.3, A = 3.0;
  ContactSettings settings{eps, 0.1, ContactQuadrature::gauss, {}};
  settings.friction = {FrictionLaw::coulomb, mu, epsT};
  const FaceNodes X = rectangle(2.0, 1.5), u = uniform(Eigen::Vector3d(0, 0, -delta));
  const auto x = contactPoints(X, u, settings.rule);
  for (const double d : {0.002, 0.02}) {  // mu eps delta / eps_T = 0.006: the first sticks
    FaceAnchors anchors;
    for (std::size_t q = 0; q < 4; ++q) anchors[q] = Eigen::Vector3d(x[q](0) - d, x[q](1), 0.0);
    FaceContactPoints points;
    const FaceForces f = faceContactForces(plane, X, u, {0, 0, 0, 0}, settings, &points, nullptr, &anchors);
    const double stickLimit = mu * eps * delta / epsT;
    const double tT = d <= stickLimit ? epsT * d : mu * eps * delta;
    EXPECT_NEAR(total(f)(0), -tT * A, 1e-9 * tT * A) << d;
    EXPECT_NEAR(total(f)(2), eps * delta * A, 1e-9 * eps * delta * A) << d;
    for (std::size_t q = 0; q < 4; ++q) {
      EXPECT_NEAR(points[q].tangential, tT, 1e-9 * tT);
      EXPECT_NEAR(points[q].slip, d <= stickLimit ? 0.0 : d - stickLimit, 1e-15);
      const double behind = d <= stickLimit ? d : stickLimit;
      EXPECT_NEAR(points[q].anchor(0), x[q](0) - behind, 1e-15) << d;
    }
  }
}

// A plane that moves +c along x under a sticking face drags it: each point, anchored where it
// touched, lies c behind its anchor, so the obstacle pulls it forward with eps_T c.
TEST(FaceFriction, MovingPlaneDragsAStickingFace) {
  const auto plane = std::make_shared<PlaneObstacle>(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1));
  const double c = 1e-3, eps = 1.0e6, epsT = 2.0e5;
  MovingObstacle moving(plane, RigidMotion({[c](double t) { return c * t; }, {}, {}}, {}));
  ContactSettings settings{eps, 0.1, ContactQuadrature::gauss, {}};
  settings.friction = {FrictionLaw::coulomb, 10.0, epsT};
  const FaceNodes X = rectangle(2.0, 1.5), u = uniform(Eigen::Vector3d(0, 0, -0.01));
  FaceContactPoints points;
  faceContactForces(moving, X, u, {0, 0, 0, 0}, settings, &points);  // at t = 0: where each point faces
  FaceAnchors anchors;
  for (std::size_t q = 0; q < 4; ++q) anchors[q] = points[q].anchor;
  moving.setTime(1.0);
  const FaceForces f = faceContactForces(moving, X, u, {0, 0, 0, 0}, settings, &points, nullptr, &anchors);
  EXPECT_NEAR(total(f)(0), epsT * c * 3.0, 1e-9 * epsT * c);
  for (std::size_t q = 0; q < 4; ++q) EXPECT_EQ(points[q].slip, 0.0);
}

// Tied: a point that touches records where (its anchor, on the obstacle); pulled back out of
// the plane by h it is held with the tension eps h; frictionless Coulomb records no anchor.
TEST(FaceFriction, TiedPointHoldsWhereItTouched) {
  const PlaneObstacle plane(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1));
  const double eps = 1.0e6, h = 0.002;
  ContactSettings settings{eps, 0.1, ContactQuadrature::nodal, {}};
  FaceContactPoints points;
  const FaceNodes X = rectangle(2.0, 1.5);
  faceContactForces(plane, X, uniform(Eigen::Vector3d(0, 0, -0.01)), {0, 0, 0, 0}, settings, &points);
  for (const auto &p : points) EXPECT_FALSE(p.anchor.allFinite());
  settings.friction.law = FrictionLaw::tied;
  faceContactForces(plane, X, uniform(Eigen::Vector3d(0, 0, -0.01)), {0, 0, 0, 0}, settings, &points);
  FaceAnchors anchors;
  for (std::size_t q = 0; q < 4; ++q) {
    anchors[q] = points[q].anchor;
    EXPECT_TRUE(anchors[q].isApprox(Eigen::Vector3d(X(q, 0), X(q, 1), 0.0), 1e-15));
  }
  const FaceForces f =
      faceContactForces(plane, X, uniform(Eigen::Vector3d(0, 0, h)), {0, 0, 0, 0}, settings, &points, nullptr, &anchors);
  EXPECT_NEAR(total(f)(2), -eps * h * 3.0, 1e-9 * eps * h);
  for (const auto &p : points) {
    EXPECT_TRUE(p.tied);
    EXPECT_TRUE(p.active());
    EXPECT_NEAR(p.pressure, -eps * h, 1e-6);
    EXPECT_EQ(gapError(p), 0.0);
  }
}
