#pragma once
// A rigid half-space bounded by the plane through `point` with unit normal `normal` pointing to
// the body's side: gap = (x - point) . normal, closest point x - gap normal, dNormal = 0.
// For verification (the contact patch test, Hertz) and flat indenters. Eigen only.

#include "contact/Obstacle.hpp"

namespace glossa::contact {

class PlaneObstacle final : public Obstacle {
public:
  // `normal` need not be unit; it is normalised (nonzero).
  PlaneObstacle(const Eigen::Vector3d &point, const Eigen::Vector3d &normal);
  std::optional<ClosestPoint> closest(const Eigen::Vector3d &x, double searchRadius) const override;

private:
  Eigen::Vector3d point_, normal_;
};

}  // namespace glossa::contact
