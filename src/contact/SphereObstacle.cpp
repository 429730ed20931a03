#include "contact/SphereObstacle.hpp"

#include <cmath>
#include <stdexcept>

namespace glossa::contact {

SphereObstacle::SphereObstacle(const Eigen::Vector3d &centre, double radius, BodySide side)
    : centre_(centre), radius_(radius), side_(side) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw std::invalid_argument("SphereObstacle: the radius must be finite and positive");
}

std::optional<ClosestPoint> SphereObstacle::closest(const Eigen::Vector3d &x, double searchRadius) const {
  return radialClosestPoint(x, centre_, Eigen::Matrix3d::Identity(), radius_, side_, searchRadius);
}

}  // namespace glossa::contact
