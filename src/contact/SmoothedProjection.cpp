#include "contact/SmoothedProjection.hpp"

#include <Eigen/Geometry>
#include <array>

#include "contact/PointTriangle.hpp"
#include "contact/SurfaceProjection.hpp"

namespace glossa::contact {

ClosestPoint projectOnSmoothedTriangle(const TriangleSurface &surface, std::size_t t, const Eigen::Vector3d &x) {
  using F = TriangleProjection::Feature;
  const TriangleSurface::Triangle &tri = surface.triangles()[t];
  const std::array<Eigen::Vector3d, 3> v{surface.corner(t, 0), surface.corner(t, 1), surface.corner(t, 2)};
  const TriangleProjection pr = closestOnTriangle(x, v[0], v[1], v[2]);
  if (onFreeBoundary(surface, t, pr)) return projectOnTriangle(surface, t, x);

  std::array<Eigen::Vector3d, 3> N;
  for (int i = 0; i < 3; ++i) N[i] = surface.vertexPseudonormal(tri[i]).normalized();
  // lambda_i and their gradients in x (rows), for the feature p lies on.
  std::array<double, 3> lambda{0, 0, 0};
  std::array<Eigen::RowVector3d, 3> dLambda{Eigen::RowVector3d::Zero(), Eigen::RowVector3d::Zero(),
                                            Eigen::RowVector3d::Zero()};
  Eigen::Matrix3d dPdx = Eigen::Matrix3d::Zero();
  if (pr.feature == F::Face) {
    const Eigen::Vector3d twiceArea = (v[1] - v[0]).cross(v[2] - v[0]);
    const Eigen::Vector3d f = twiceArea.normalized();
    const double A2 = twiceArea.norm();
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d &b = v[(i + 1) % 3], &c = v[(i + 2) % 3];
      // lambda_i = ((c - b) x (p - b)) . f / 2A: its gradient f x (c - b) / 2A lies in the plane.
      lambda[i] = (c - b).cross(pr.point - b).dot(f) / A2;
      dLambda[i] = f.cross(c - b).transpose() / A2;
    }
    dPdx = Eigen::Matrix3d::Identity() - f * f.transpose();
  } else if (pr.feature == F::Edge) {
    const int i = pr.index, j = (pr.index + 1) % 3;
    const Eigen::Vector3d edge = v[j] - v[i];
    const double L = edge.norm();
    const Eigen::Vector3d e = edge / L;
    lambda[j] = (pr.point - v[i]).dot(e) / L;
    lambda[i] = 1.0 - lambda[j];
    dLambda[j] = e.transpose() / L;
    dLambda[i] = -dLambda[j];
    dPdx = e * e.transpose();
  } else {
    lambda[pr.index] = 1.0;  // p is the corner itself, fixed as x moves: dLambda = 0
  }

  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d dm = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i) {
    m += lambda[i] * N[i];
    dm += N[i] * dLambda[i];
  }
  const double length = m.norm();
  // Vertex normals that cancel (a knife edge folded back on itself) give no direction.
  if (!(length > 1e-8)) return projectOnTriangle(surface, t, x);
  ClosestPoint cp;
  cp.point = pr.point;
  cp.normal = m / length;
  const Eigen::Vector3d d = x - pr.point;
  cp.gap = d.dot(cp.normal);
  cp.dNormal = (Eigen::Matrix3d::Identity() - cp.normal * cp.normal.transpose()) * dm / length;
  cp.dGap = (Eigen::Matrix3d::Identity() - dPdx).transpose() * cp.normal + cp.dNormal.transpose() * d;
  return cp;
}

}  // namespace glossa::contact
