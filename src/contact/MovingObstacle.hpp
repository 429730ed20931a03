#pragma once
// Any obstacle moved rigidly in time (RigidMotion): a query point is taken back to the
// obstacle's own frame, the obstacle answers there, and its answer is carried forward: the point
// by the motion, the normal rotated, dNormal = R dN R^T; the gap is unchanged (a rigid motion
// keeps distances). The pose is that of the time last set.

#include <memory>

#include "contact/Obstacle.hpp"
#include "contact/RigidMotion.hpp"

namespace glossa::contact {

class MovingObstacle : public Obstacle {
 public:
  MovingObstacle(std::shared_ptr<const Obstacle> obstacle, RigidMotion motion);

  // The time whose pose the queries use (0 until set).
  void setTime(double t);
  const RigidPose &pose() const { return pose_; }

  std::optional<ClosestPoint> closest(const Eigen::Vector3d &x, double searchRadius) const override;
  Eigen::Vector3d toWorld(const Eigen::Vector3d &X) const override { return pose_.toWorld(X); }
  Eigen::Vector3d toBody(const Eigen::Vector3d &x) const override { return pose_.toBody(x); }

 private:
  std::shared_ptr<const Obstacle> obstacle_;
  RigidMotion motion_;
  RigidPose pose_;
};

}  // namespace glossa::contact
