// GaussNewtonController on model problems with known minimisers: a linear control map (one
// Gauss-Newton step is exact), a nonlinear map whose constrained minimiser is known in closed
// form, an unreachable goal that ends on the bound, monotone descent, the stop reasons, and a
// failed start.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "control/GaussNewtonController.hpp"

namespace glossa::control {
namespace {

// r(u) = M u + c (three "points" in 1D), objective eq. 25 as the sum of |r_p|.
struct LinearPlant {
  Eigen::MatrixXd M;
  Eigen::VectorXd c;
  int evaluations = 0;
  ControlEvaluation operator()(const Eigen::VectorXd &u) {
    ++evaluations;
    ControlEvaluation e;
    e.ok = true;
    e.residual = M * u + c;
    e.objective = e.residual.cwiseAbs().sum();
    return e;
  }
};

TEST(GaussNewtonController, OneStepSolvesALinearPlantWithAReachableGoal) {
  LinearPlant plant;
  plant.M.resize(3, 2);
  plant.M << 1.0, 0.2, -0.5, 1.0, 0.3, 0.3;
  const Eigen::Vector2d target(0.4, 0.7);
  plant.c = -plant.M * target;
  GaussNewtonParameters p;
  p.damping = 0.0;
  p.objectiveTolerance = 1e-12;
  const GaussNewtonController controller(p);
  const auto r = controller.minimise(Eigen::Vector2d(0.0, 0.0), std::ref(plant),
                                     [&](const Eigen::VectorXd &) { return Eigen::MatrixXd(plant.M); });
  EXPECT_LT((r.inputs - target).norm(), 1e-12);
  EXPECT_EQ(r.stop, GaussNewtonStop::objectiveTolerance);
  EXPECT_EQ(r.sensitivities, 1);
  EXPECT_EQ(r.evaluations, 2);
}

TEST(GaussNewtonController, EndsOnTheBoundWhenTheGoalIsOutOfReach) {
  LinearPlant plant;
  plant.M = Eigen::MatrixXd::Identity(2, 2);
  plant.c = Eigen::Vector2d(-1.5, -0.25); // goal u = (1.5, 0.25): u_0 clipped to 1
  const GaussNewtonController controller(GaussNewtonParameters{});
  const auto r = controller.minimise(Eigen::Vector2d(0.5, 0.5), std::ref(plant),
                                     [&](const Eigen::VectorXd &) { return Eigen::MatrixXd(plant.M); });
  EXPECT_NEAR(r.inputs(0), 1.0, 1e-12);
  EXPECT_NEAR(r.inputs(1), 0.25, 1e-5);
  EXPECT_NEAR(r.objective, 0.5, 1e-5);
  EXPECT_EQ(r.stop, GaussNewtonStop::stationary);
}

// A nonlinear plant: two muscles pull a point along x with saturating force, one also along y;
// r(u) = (tanh(2 u0) + 0.5 u1^2 - a, u1 (1 - 0.3 u0) - b). Goals chosen from a known u*.
TEST(GaussNewtonController, ConvergesOnANonlinearPlantAndTheSumOfSquaresNeverRises) {
  const Eigen::Vector2d uStar(0.35, 0.6);
  auto map = [](const Eigen::VectorXd &u) {
    return Eigen::Vector2d(std::tanh(2.0 * u(0)) + 0.5 * u(1) * u(1), u(1) * (1.0 - 0.3 * u(0)));
  };
  const Eigen::Vector2d goal = map(uStar);
  std::vector<double> accepted;
  Eigen::VectorXd last;
  auto evaluate = [&](const Eigen::VectorXd &u) {
    ControlEvaluation e;
    e.ok = true;
    e.residual = map(u) - goal;
    e.objective = e.residual.norm();
    return e;
  };
  auto jacobian = [&](const Eigen::VectorXd &u) {
    accepted.push_back((map(u) - goal).squaredNorm());
    Eigen::MatrixXd J(2, 2);
    const double s = 1.0 / std::cosh(2.0 * u(0));
    J << 2.0 * s * s, u(1), -0.3 * u(1), 1.0 - 0.3 * u(0);
    return J;
  };
  GaussNewtonParameters p;
  p.maxIterations = 12;
  p.stepTolerance = 1e-9;
  const GaussNewtonController controller(p);
  const auto r = controller.minimise(Eigen::Vector2d(1.0, 0.0), evaluate, jacobian);
  EXPECT_LT((r.inputs - uStar).norm(), 1e-7);
  for (std::size_t k = 1; k < accepted.size(); ++k) EXPECT_LT(accepted[k], accepted[k - 1]);
  EXPECT_GE(r.iterations, 2); // nonlinear: more than one step
}

TEST(GaussNewtonController, WrongSensitivityFallsBackToNoDescent) {
  LinearPlant plant;
  plant.M = Eigen::MatrixXd::Identity(1, 1);
  plant.c = Eigen::VectorXd::Constant(1, -0.5);
  GaussNewtonParameters p;
  p.maxBacktracks = 2;
  const GaussNewtonController controller(p);
  // A sensitivity of the wrong sign: every step goes uphill, the start is kept.
  const auto r = controller.minimise(Eigen::VectorXd::Constant(1, 0.25), std::ref(plant),
                                     [](const Eigen::VectorXd &) { return Eigen::MatrixXd::Constant(1, 1, -1.0); });
  EXPECT_EQ(r.stop, GaussNewtonStop::noDescent);
  EXPECT_EQ(r.inputs(0), 0.25);
  EXPECT_EQ(r.evaluations, 1 + 3);
}

TEST(GaussNewtonController, FailedStartIsReported) {
  const GaussNewtonController controller(GaussNewtonParameters{});
  const auto r = controller.minimise(
      Eigen::VectorXd::Zero(2), [](const Eigen::VectorXd &) { return ControlEvaluation{}; },
      [](const Eigen::VectorXd &) { return Eigen::MatrixXd(); });
  EXPECT_EQ(r.stop, GaussNewtonStop::startFailed);
  EXPECT_FALSE(std::isfinite(r.objective));
}

TEST(GaussNewtonController, ValidatesItsParameters) {
  GaussNewtonParameters p;
  p.maxIterations = 0;
  EXPECT_THROW(GaussNewtonController{p}, std::invalid_argument);
  p = {};
  p.stepTolerance = 0.0;
  EXPECT_THROW(GaussNewtonController{p}, std::invalid_argument);
  p = {};
  p.damping = -1.0;
  EXPECT_THROW(GaussNewtonController{p}, std::invalid_argument);
}

}  // namespace
}  // namespace glossa::control
