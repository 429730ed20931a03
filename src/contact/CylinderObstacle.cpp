#include "contact/CylinderObstacle.hpp"

#include <cmath>
#include <stdexcept>

namespace glossa::contact {

CylinderObstacle::CylinderObstacle(const Eigen::Vector3d &axisPoint, const Eigen::Vector3d &axis, double radius,
                                   BodySide side)
    : axisPoint_(axisPoint), radius_(radius), side_(side) {
  const double length = axis.norm();
  if (!(length > 0.0) || !std::isfinite(length))
    throw std::invalid_argument("CylinderObstacle: the axis must be a finite nonzero vector");
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw std::invalid_argument("CylinderObstacle: the radius must be finite and positive");
  axis_ = axis / length;
  P_ = Eigen::Matrix3d::Identity() - axis_ * axis_.transpose();
}

std::optional<ClosestPoint> CylinderObstacle::closest(const Eigen::Vector3d &x, double searchRadius) const {
  // P (x - axisPoint) = P (x - c): the axis point nearest to x differs from axisPoint along e only.
  return radialClosestPoint(x, axisPoint_, P_, radius_, side_, searchRadius);
}

}  // namespace glossa::contact
