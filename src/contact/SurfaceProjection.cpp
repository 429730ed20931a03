#include "contact/SurfaceProjection.hpp"

#include <limits>

#include "contact/PointTriangle.hpp"

namespace glossa::contact {

namespace {
// Below this fraction of the triangle's size, x is on the edge or corner itself and (x - p)
// has no direction: the pseudonormal gives the normal.
constexpr double kOnFeature = 1e-12;
}  // namespace

bool onFreeBoundary(const TriangleSurface &surface, std::size_t t, const TriangleProjection &pr) {
  using F = TriangleProjection::Feature;
  return pr.feature == F::Edge     ? surface.onFreeBoundary(t, pr.index)
         : pr.feature == F::Vertex ? surface.onFreeBoundary(surface.triangles()[t][pr.index])
                                   : false;
}

ClosestPoint projectOnTriangle(const TriangleSurface &surface, std::size_t t, const Eigen::Vector3d &x,
                               bool *besideFreeBoundary) {
  using F = TriangleProjection::Feature;
  const Eigen::Vector3d a = surface.corner(t, 0), b = surface.corner(t, 1), c = surface.corner(t, 2);
  const TriangleProjection pr = closestOnTriangle(x, a, b, c);
  ClosestPoint cp;
  cp.point = pr.point;
  const Eigen::Vector3d d = x - pr.point;
  const bool onRim = onFreeBoundary(surface, t, pr);
  if (besideFreeBoundary) *besideFreeBoundary = onRim;
  if (pr.feature == F::Face) {
    cp.normal = surface.normal(t);
    cp.gap = d.dot(cp.normal);
    return cp;
  }
  const Eigen::Vector3d pseudo = pr.feature == F::Edge
                                     ? surface.edgePseudonormal(t, pr.index)
                                     : surface.vertexPseudonormal(surface.triangles()[t][pr.index]);
  const double distance = d.norm();
  const double size = (b - a).norm() + (c - a).norm();
  if (distance <= kOnFeature * size) {
    const double length = pseudo.norm();
    cp.normal = length > 0 ? Eigen::Vector3d(pseudo / length) : surface.normal(t);
    cp.gap = d.dot(cp.normal);
    return cp;
  }
  const double sign = !onRim && d.dot(pseudo) < 0 ? -1.0 : 1.0;
  cp.normal = sign * d / distance;
  cp.gap = sign * distance;
  Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - cp.normal * cp.normal.transpose();
  if (pr.feature == F::Edge) {
    const Eigen::Vector3d e =
        (surface.corner(t, (pr.index + 1) % 3) - surface.corner(t, pr.index)).normalized();
    P -= e * e.transpose();
  }
  cp.dNormal = P / cp.gap;
  return cp;
}

std::size_t closestTriangleByScan(const TriangleSurface &surface, const Eigen::Vector3d &x) {
  std::size_t best = 0;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < surface.numTriangles(); ++t) {
    const double d =
        (x - closestOnTriangle(x, surface.corner(t, 0), surface.corner(t, 1), surface.corner(t, 2)).point)
            .squaredNorm();
    if (d < bestDistance) {
      bestDistance = d;
      best = t;
    }
  }
  return best;
}

}  // namespace glossa::contact
