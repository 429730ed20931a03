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

loads::FaceForces faceContactForces(const Obstacle &obstacle, const loads::FaceNodes &X,
                                    const loads::FaceNodes &u, const FaceMultipliers &lambda,
                                    const ContactSettings &settings, FaceContactPoints *points,
                                    loads::FaceTangent *K) {
  const loads::FaceNodes x = X + u;
  const double eps = settings.penalty;
  loads::FaceForces f = loads::FaceForces::Zero();
  if (K) K->setZero();
  const auto &coordinates = contactPointCoordinates(settings.rule);
  for (std::size_t q = 0; q < 4; ++q) {
    const loads::FaceShape shape = loads::faceShape(coordinates[q](0), coordinates[q](1));
    const Eigen::Vector3d xq = x.transpose() * shape.N;
    const std::optional<ClosestPoint> cp = obstacle.closest(xq, settings.searchRadius);
    ContactPointState state;
    state.gap = cp ? cp->gap : std::numeric_limits<double>::infinity();
    const double trial = cp ? lambda[q] - eps * cp->gap : -1.0;
    state.pressure = std::max(0.0, trial);
    const Eigen::Vector3d xs = x.transpose() * shape.dNds, xt = x.transpose() * shape.dNdt;
    const Eigen::Vector3d area = xs.cross(xt);
    const double j = area.norm(), t = state.pressure;
    state.area = j; // both rules weigh each point by 1
    if (points) (*points)[q] = state;
    // At the kink (trial = 0: touching at zero gap, no multiplier) the point carries nothing
    // but gives the tangent of the contact side, so that a body resting on an obstacle has its
    // stiffness from the first Newton iteration rather than a singular direction.
    if (trial < 0.0) continue;

    const Eigen::Vector3d &n = cp->normal;
    // Both rules weigh each point by 1.
    for (int a = 0; a < 4; ++a) f.segment<3>(3 * a) += t * j * shape.N(a) * n;
    if (!K || j == 0.0) continue;

    // d(t n j)/dx_q at fixed area: t = lambda - eps g with dg/dx = n^T, dn/dx = dNormal; x_q
    // moves with node b by N_b.
    const Eigen::Matrix3d atPoint = j * (-eps * n * n.transpose() + t * cp->dNormal);
    // dj/du_b = m^T d(x_,s x x_,t)/du_b, m the face's unit normal.
    const Eigen::RowVector3d mT = area.transpose() / j;
    const Eigen::Matrix3d Ss = loads::crossMatrix(xs), St = loads::crossMatrix(xt);
    for (int b = 0; b < 4; ++b) {
      const Eigen::Matrix3d dtnj =
          shape.N(b) * atPoint + t * n * (mT * (shape.dNdt(b) * Ss - shape.dNds(b) * St));
      for (int a = 0; a < 4; ++a) K->block<3, 3>(3 * a, 3 * b) += shape.N(a) * dtnj;
    }
  }
  return f;
}

double updatedMultiplier(double lambda, double penalty, double gap) {
  return std::max(0.0, lambda - penalty * gap);
}

double gapError(const ContactPointState &point) { return point.active() ? std::abs(point.gap) : 0.0; }

}  // namespace glossa::contact
