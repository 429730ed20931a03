#include "contact/RigidMotion.hpp"

#include <Eigen/Geometry>
#include <stdexcept>

namespace glossa::contact {

RigidMotion::RigidMotion(std::array<TimeFunctionOfT, 3> translation, std::vector<AxisRotation> rotations,
                         const Eigen::Vector3d &pivot)
    : translation_(std::move(translation)), rotations_(std::move(rotations)), pivot_(pivot) {
  for (AxisRotation &r : rotations_) {
    const double length = r.axis.norm();
    if (!(length > 0)) throw std::invalid_argument("a rotation of a rigid motion needs a non-zero axis");
    r.axis /= length;
  }
}

RigidPose RigidMotion::at(double t) const {
  RigidPose pose;
  pose.pivot = pivot_;
  for (int d = 0; d < 3; ++d) pose.c[d] = translation_[d] ? translation_[d](t) : 0.0;
  for (const AxisRotation &r : rotations_) {
    const double theta = r.angle ? r.angle(t) : 0.0;
    pose.R = Eigen::AngleAxisd(theta, r.axis).toRotationMatrix() * pose.R;
  }
  return pose;
}

}  // namespace glossa::contact
