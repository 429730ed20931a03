#include "contact/RadialSurface.hpp"

#include <cmath>

namespace glossa::contact {

std::optional<ClosestPoint> radialClosestPoint(const Eigen::Vector3d &x, const Eigen::Vector3d &c,
                                               const Eigen::Matrix3d &P, double R, BodySide side,
                                               double searchRadius) {
  const Eigen::Vector3d d = P * (x - c);
  const double r = d.norm();
  const double s = side == BodySide::outside ? 1.0 : -1.0;
  const double gap = s * (r - R);
  if (r == 0.0 || std::abs(gap) > searchRadius) return std::nullopt;
  ClosestPoint cp;
  const Eigen::Vector3d radial = d / r;
  cp.normal = s * radial;
  cp.point = x - (r - R) * radial;
  cp.gap = gap;
  // d(d/r)/dx = (P - radial radial^T) / r, since dd/dx = P, P d = d and n n^T = radial radial^T.
  cp.dNormal = s * (P - radial * radial.transpose()) / r;
  return cp;
}

}  // namespace glossa::contact
