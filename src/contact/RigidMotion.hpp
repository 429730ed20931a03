#pragma once
// A rigid motion in time: a point X of an obstacle, given in its file's frame, is at
//   x(t) = pivot + c(t) + R(t) (X - pivot)
// with c(t) the three translations and R(t) = R_n(theta_n(t)) ... R_1(theta_1(t)) rotations by
// the angles theta_k(t) [rad] about the fixed axes a_k through the pivot, the first applied
// first (three angles about x, y, z; or a single axis and angle). Each is a time function: any
// callable of t, a model::TimeFunction included; an empty one is 0.

#include <Eigen/Core>
#include <array>
#include <functional>
#include <vector>

namespace glossa::contact {

using TimeFunctionOfT = std::function<double(double)>;

struct AxisRotation {
  Eigen::Vector3d axis;   // need not be unit; not zero
  TimeFunctionOfT angle;  // [rad]
};

// Where the obstacle is at one time: x = pivot + c + R (X - pivot).
struct RigidPose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();
  Eigen::Vector3d toWorld(const Eigen::Vector3d &X) const { return pivot + c + R * (X - pivot); }
  Eigen::Vector3d toBody(const Eigen::Vector3d &x) const { return pivot + R.transpose() * (x - pivot - c); }
};

class RigidMotion {
 public:
  // At rest: the identity at every time.
  RigidMotion() = default;
  // Throws std::invalid_argument for a zero axis.
  RigidMotion(std::array<TimeFunctionOfT, 3> translation, std::vector<AxisRotation> rotations,
              const Eigen::Vector3d &pivot = Eigen::Vector3d::Zero());

  RigidPose at(double t) const;

 private:
  std::array<TimeFunctionOfT, 3> translation_;
  std::vector<AxisRotation> rotations_;
  Eigen::Vector3d pivot_ = Eigen::Vector3d::Zero();
};

}  // namespace glossa::contact
