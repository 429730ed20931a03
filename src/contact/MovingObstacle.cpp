#include "contact/MovingObstacle.hpp"

namespace glossa::contact {

MovingObstacle::MovingObstacle(std::shared_ptr<const Obstacle> obstacle, RigidMotion motion)
    : obstacle_(std::move(obstacle)), motion_(std::move(motion)), pose_(motion_.at(0.0)) {}

void MovingObstacle::setTime(double t) { pose_ = motion_.at(t); }

std::optional<ClosestPoint> MovingObstacle::closest(const Eigen::Vector3d &x, double searchRadius) const {
  std::optional<ClosestPoint> cp = obstacle_->closest(pose_.toBody(x), searchRadius);
  if (!cp) return cp;
  cp->point = pose_.toWorld(cp->point);
  cp->normal = pose_.R * cp->normal;
  cp->dNormal = pose_.R * cp->dNormal * pose_.R.transpose();
  if (cp->dGap) cp->dGap = pose_.R * *cp->dGap;
  return cp;
}

}  // namespace glossa::contact
