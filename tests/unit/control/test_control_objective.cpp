// ControlObjective (eq. 25) against hand-computed distances.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "control/ControlObjective.hpp"

namespace glossa::control {
namespace {

TEST(ControlObjective, HandValues) {
  Eigen::Matrix3Xd goal(3, 3), x(3, 3);
  goal.col(0) << 0, 0, 0;
  goal.col(1) << 1, 1, 1;
  goal.col(2) << -1, 2, 0.5;
  x.col(0) << 1, 2, 2;     // distance 3
  x.col(1) << 1, 4, 5;     // distance sqrt(0 + 9 + 16) = 5
  x.col(2) << -1, 2, 0.5;  // at its goal
  Eigen::VectorXd w(3);
  w << 1.0, 0.5, 7.0;
  const ControlObjectiveValue v = ControlObjective(goal, w).evaluate(x);
  ASSERT_EQ(v.distance.size(), 3);
  EXPECT_DOUBLE_EQ(v.distance[0], 3.0);
  EXPECT_DOUBLE_EQ(v.distance[1], 5.0);
  EXPECT_DOUBLE_EQ(v.distance[2], 0.0);
  EXPECT_DOUBLE_EQ(v.weightedError[0], 3.0);
  EXPECT_DOUBLE_EQ(v.weightedError[1], 2.5);
  EXPECT_DOUBLE_EQ(v.weightedError[2], 0.0);
  // A sum of norms (eq. 25), not of squares (which would give 9 + 12.5 = 21.5) or a global norm.
  EXPECT_DOUBLE_EQ(v.total, 5.5);
}

TEST(ControlObjective, UnitWeightsByDefaultAndZeroWeightIgnoresAPoint) {
  Eigen::Matrix3Xd goal = Eigen::Matrix3Xd::Zero(3, 2), x(3, 2);
  x.col(0) << 0, 0, 2;
  x.col(1) << 3, 0, 4;
  EXPECT_DOUBLE_EQ(ControlObjective(goal).evaluate(x).total, 7.0);
  Eigen::VectorXd w(2);
  w << 0.0, 1.0;
  EXPECT_DOUBLE_EQ(ControlObjective(goal, w).evaluate(x).total, 5.0);
}

TEST(ControlObjective, RejectsBadInput) {
  const Eigen::Matrix3Xd goal = Eigen::Matrix3Xd::Zero(3, 2);
  EXPECT_THROW(ControlObjective(goal, Eigen::VectorXd::Ones(3)), std::invalid_argument);
  EXPECT_THROW(ControlObjective(goal, Eigen::Vector2d(1.0, -0.1)), std::invalid_argument);
  EXPECT_THROW(ControlObjective(goal, Eigen::Vector2d(1.0, std::numeric_limits<double>::infinity())),
               std::invalid_argument);
  EXPECT_THROW(ControlObjective(goal).evaluate(Eigen::Matrix3Xd::Zero(3, 3)), std::invalid_argument);
}

}  // namespace
}  // namespace glossa::control
