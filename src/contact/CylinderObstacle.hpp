#pragma once
// A rigid circular cylinder of infinite length: the axis through `axisPoint` along `axis`,
// radius R; the body outside it (a cylindrical indenter, the ironing die, Hertz in plane
// strain) or inside it (a tube). With e the unit axis, c = a + ((x - a) . e) e the axis point
// nearest to x and P = I - e e: n = +-P (x - c)/r, gap = +-(r - R), dNormal = +-(P - n n)/r,
// r = |P (x - c)| (+ outside, - inside). Eigen only.

#include "contact/Obstacle.hpp"
#include "contact/RadialSurface.hpp"

namespace glossa::contact {

class CylinderObstacle final : public Obstacle {
public:
  // `axis` need not be unit (nonzero); R > 0.
  CylinderObstacle(const Eigen::Vector3d &axisPoint, const Eigen::Vector3d &axis, double radius,
                   BodySide side = BodySide::outside);
  std::optional<ClosestPoint> closest(const Eigen::Vector3d &x, double searchRadius) const override;

private:
  Eigen::Vector3d axisPoint_, axis_;
  Eigen::Matrix3d P_;  // I - e e: onto the plane normal to the axis
  double radius_;
  BodySide side_;
};

}  // namespace glossa::contact
