#pragma once
// The control objective of eq. 25 (paper §6.1, doc/control.md):
//
//   J = sum_p || w_p (x_p - xbar_p) ||_2  =  sum_p w_p ||x_p - xbar_p||_2   (w_p >= 0)
//
// over control points p at current positions x_p with goal positions xbar_p (position
// maintenance: their positions at a reference time). A sum of distances, not of squared
// distances, as in the paper: every point pulls with the same weight however close it is.

#include <Eigen/Core>

namespace glossa::control {

struct ControlObjectiveValue {
  double total = 0.0;             // J of eq. 25
  Eigen::VectorXd distance;       // ||x_p - xbar_p|| per point (unweighted, for output)
  Eigen::VectorXd weightedError;  // w_p ||x_p - xbar_p|| per point; sums to `total`
};

class ControlObjective {
 public:
  // goal: 3 x P goal positions; weights: P values >= 0 (the paper uses w_p = 1). Throws
  // std::invalid_argument for a size mismatch, a negative or non-finite weight, or a non-finite
  // goal.
  ControlObjective(Eigen::Matrix3Xd goal, Eigen::VectorXd weights);
  // All weights 1.
  explicit ControlObjective(Eigen::Matrix3Xd goal);

  // x: 3 x P current positions of the same points, in the same order. Throws
  // std::invalid_argument on a size mismatch.
  ControlObjectiveValue evaluate(const Eigen::Matrix3Xd &x) const;

  Eigen::Index pointCount() const { return goal_.cols(); }
  const Eigen::Matrix3Xd &goal() const { return goal_; }
  const Eigen::VectorXd &weights() const { return weights_; }

 private:
  Eigen::Matrix3Xd goal_;
  Eigen::VectorXd weights_;
};

}  // namespace glossa::control
