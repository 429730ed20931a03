#pragma once
// A rigid sphere of centre c and radius R (an indenter, Hertz), with the body outside it, or a
// rigid spherical cavity with the body inside. Outside: n = (x - c)/|x - c|, gap = |x - c| - R,
// dNormal = (I - n n)/(R + gap); inside: n = (c - x)/|x - c|, gap = R - |x - c|,
// dNormal = -(I - n n)/(R - gap). Eigen only.

#include "contact/Obstacle.hpp"
#include "contact/RadialSurface.hpp"

namespace glossa::contact {

class SphereObstacle final : public Obstacle {
public:
  // R > 0.
  SphereObstacle(const Eigen::Vector3d &centre, double radius, BodySide side = BodySide::outside);
  std::optional<ClosestPoint> closest(const Eigen::Vector3d &x, double searchRadius) const override;

private:
  Eigen::Vector3d centre_;
  double radius_;
  BodySide side_;
};

}  // namespace glossa::contact
