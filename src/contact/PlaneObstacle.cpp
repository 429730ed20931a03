#include "contact/PlaneObstacle.hpp"

#include <cmath>
#include <stdexcept>

namespace glossa::contact {

PlaneObstacle::PlaneObstacle(const Eigen::Vector3d &point, const Eigen::Vector3d &normal) : point_(point) {
  const double length = normal.norm();
  if (!(length > 0.0) || !std::isfinite(length))
    throw std::invalid_argument("PlaneObstacle: the normal must be a finite nonzero vector");
  normal_ = normal / length;
}

std::optional<ClosestPoint> PlaneObstacle::closest(const Eigen::Vector3d &x, double searchRadius) const {
  const double gap = (x - point_).dot(normal_);
  if (std::abs(gap) > searchRadius) return std::nullopt;
  ClosestPoint cp;
  cp.point = x - gap * normal_;
  cp.normal = normal_;
  cp.gap = gap;
  return cp;  // dNormal stays zero: the normal is the same everywhere
}

}  // namespace glossa::contact
