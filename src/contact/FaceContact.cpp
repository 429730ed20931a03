#include "contact/FaceContact.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "loads/FaceShape.hpp"

namespace glossa::contact {

const std::array<Eigen::Vector2d, 4> &contactPointCoordinates(ContactQuadrature rule) {
  static const std::array<Eigen::Vector2d, 4> gauss = [] {
    const double g = 1.0 / std::sqrt(3.0);
    return std::array<Eigen::Vector2d, 4>{Eigen::Vector2d(-g, -g), Eigen::Vector2d(g, -g),
                                          Eigen::Vector2d(g, g), Eigen::Vector2d(-g, g)};
  }();
  static const std::array<Eigen::Vector2d, 4> nodal{Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, -1),
                                                    Eigen::Vector2d(1, 1), Eigen::Vector2d(-1, 1)};
  return rule == ContactQuadrature::gauss ? gauss : nodal;
}

namespace {

// One contact point's traction t (the obstacle's push on the body per deformed area: t_N n + t_T,
// or tied contact's) and dt/dx_q at fixed area, its state filled; false if it carries nothing and
// has no tangent (apart, or beyond the kink).
bool pointTraction(const Obstacle &obstacle, const Eigen::Vector3d &xq, const std::optional<ClosestPoint> &cp,
                   double lambda, const Eigen::Vector3d &anchorIn, const ContactSettings &settings,
                   ContactPointState &state, Eigen::Vector3d &t, Eigen::Matrix3d &dt) {
  const double eps = settings.penalty;
  const FrictionSettings &friction = settings.friction;
  const bool anchored = anchorIn.allFinite();
  state.gap = cp ? cp->gap : std::numeric_limits<double>::infinity();
  if (friction.law == FrictionLaw::tied && anchored) {
    // Tied once touched, apart or not: the anchor holds it in every direction.
    const TangentialTraction r = tiedTraction(xq, obstacle.toWorld(anchorIn), eps);
    t = r.traction;
    dt = r.dTraction;
    state.tied = true;
    state.anchor = anchorIn;
    const double tN = cp ? t.dot(cp->normal) : 0.0;
    state.pressure = tN;
    state.tangential = cp ? (t - tN * cp->normal).norm() : t.norm();
    return true;
  }
  const double trial = cp ? lambda - eps * cp->gap : -1.0;
  state.pressure = std::max(0.0, trial);
  // A Coulomb point within the search radius but apart faces the obstacle's closest point: its
  // slip, once it touches, is measured from there.
  if (cp && friction.frictional()) state.anchor = obstacle.toBody(cp->point);
  // At the kink (trial = 0: touching at zero gap, no multiplier) the point carries nothing but
  // gives the tangent of the contact side, so that a body resting on an obstacle has its
  // stiffness from the first Newton iteration rather than a singular direction.
  if (trial < 0.0) return false;
  const Eigen::Vector3d &n = cp->normal;
  const double tN = state.pressure;
  t = tN * n;
  // t = lambda - eps g with dg/dx = the gap's gradient (n^T but on smoothed normals), dn/dx = dNormal.
  dt = -eps * n * cp->gapGradient().transpose() + tN * cp->dNormal;
  if (friction.law == FrictionLaw::tied) {
    if (tN > 0.0) state.anchor = obstacle.toBody(cp->point);  // touched: tied from the next step on
    return true;
  }
  // A point without an anchor (it was not within the search radius) has no slip to measure yet.
  if (!friction.frictional() || !anchored) return true;
  const TangentialTraction r = coulombTraction(xq, obstacle.toWorld(anchorIn), *cp, tN, eps, friction);
  t += r.traction;
  dt += r.dTraction;
  state.anchor = obstacle.toBody(r.anchor);
  state.slip = r.slip;
  state.tangential = r.traction.norm();
  return true;
}

}  // namespace

loads::FaceForces faceContactForces(const Obstacle &obstacle, const loads::FaceNodes &X,
                                    const loads::FaceNodes &u, const FaceMultipliers &lambda,
                                    const ContactSettings &settings, FaceContactPoints *points,
                                    loads::FaceTangent *K, const FaceAnchors *anchors) {
  const loads::FaceNodes x = X + u;
  loads::FaceForces f = loads::FaceForces::Zero();
  if (K) K->setZero();
  const Eigen::Vector3d none = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  const auto &coordinates = contactPointCoordinates(settings.rule);
  for (std::size_t q = 0; q < 4; ++q) {
    const loads::FaceShape shape = loads::faceShape(coordinates[q](0), coordinates[q](1));
    const Eigen::Vector3d xq = x.transpose() * shape.N;
    const std::optional<ClosestPoint> cp = obstacle.closest(xq, settings.searchRadius);
    const Eigen::Vector3d xs = x.transpose() * shape.dNds, xt = x.transpose() * shape.dNdt;
    const Eigen::Vector3d area = xs.cross(xt);
    const double j = area.norm();
    ContactPointState state;
    state.area = j; // both rules weigh each point by 1
    Eigen::Vector3d t;
    Eigen::Matrix3d dt;
    const bool carries = pointTraction(obstacle, xq, cp, lambda[q], anchors ? (*anchors)[q] : none, settings, state, t, dt);
    if (points) (*points)[q] = state;
    if (!carries) continue;

    // Both rules weigh each point by 1.
    for (int a = 0; a < 4; ++a) f.segment<3>(3 * a) += j * shape.N(a) * t;
    if (!K || j == 0.0) continue;

    // d(t j)/dx_q at fixed area; x_q moves with node b by N_b.
    const Eigen::Matrix3d atPoint = j * dt;
    // dj/du_b = m^T d(x_,s x x_,t)/du_b, m the face's unit normal.
    const Eigen::RowVector3d mT = area.transpose() / j;
    const Eigen::Matrix3d Ss = loads::crossMatrix(xs), St = loads::crossMatrix(xt);
    for (int b = 0; b < 4; ++b) {
      const Eigen::Matrix3d dtj = shape.N(b) * atPoint + t * (mT * (shape.dNdt(b) * Ss - shape.dNds(b) * St));
      for (int a = 0; a < 4; ++a) K->block<3, 3>(3 * a, 3 * b) += shape.N(a) * dtj;
    }
  }
  return f;
}

double updatedMultiplier(double lambda, double penalty, double gap) {
  return std::max(0.0, lambda - penalty * gap);
}

double gapError(const ContactPointState &point) {
  return point.active() && !point.tied ? std::abs(point.gap) : 0.0;
}

}  // namespace glossa::contact
