#include "control/ControlObjective.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace glossa::control {

ControlObjective::ControlObjective(Eigen::Matrix3Xd goal, Eigen::VectorXd weights)
    : goal_(std::move(goal)), weights_(std::move(weights)) {
  if (weights_.size() != goal_.cols()) {
    std::ostringstream s;
    s << "ControlObjective: " << weights_.size() << " weights for " << goal_.cols() << " control points";
    throw std::invalid_argument(s.str());
  }
  if (!goal_.allFinite()) throw std::invalid_argument("ControlObjective: a goal position is not finite");
  for (Eigen::Index p = 0; p < weights_.size(); ++p)
    if (!(weights_[p] >= 0.0) || !std::isfinite(weights_[p])) {
      std::ostringstream s;
      s << "ControlObjective: weight of point " << p << " = " << weights_[p]
        << " is out of range: allowed [0, inf)";
      throw std::invalid_argument(s.str());
    }
}

ControlObjective::ControlObjective(Eigen::Matrix3Xd goal)
    : ControlObjective(goal, Eigen::VectorXd::Ones(goal.cols())) {}

ControlObjectiveValue ControlObjective::evaluate(const Eigen::Matrix3Xd &x) const {
  if (x.cols() != goal_.cols()) {
    std::ostringstream s;
    s << "ControlObjective: " << x.cols() << " positions for " << goal_.cols() << " control points";
    throw std::invalid_argument(s.str());
  }
  ControlObjectiveValue v;
  v.distance = (x - goal_).colwise().norm().transpose();
  // eq. 25: || w_p (x_p - xbar_p) || = w_p ||x_p - xbar_p|| for a scalar w_p >= 0.
  v.weightedError = weights_.cwiseProduct(v.distance);
  v.total = v.weightedError.sum();
  return v;
}

}  // namespace glossa::control
