// The control driver on a linear fake plant (LinearPlant.hpp: d = A u), without a deck or a
// solve: the GA's winner against the brute-force optimum over the binary inputs, the gradient
// controller against the inputs that put the points on their goals, pruning, failed candidates,
// and the finite-difference check of the sensitivities.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "LinearPlant.hpp"
#include "solvers/ControlDriver.hpp"

using glossa::solvers::ControlDriver;
using glossa::solvers::ControlDriverSetup;
using glossa::solvers::ControlStepResult;
using glossa::solvers::SingleControlGroup;
using glossa::test::LinearPlant;

namespace {
constexpr int kGroups = 4;

// Two points, four groups; column M is how group M moves the points (mm-scale, like the block).
Eigen::MatrixXd plantMatrix() {
  Eigen::MatrixXd A(6, kGroups);
  A << 1.0, -0.5, 0.2, 0.0, //
      0.3, 1.2, -0.4, 0.1,  //
      -0.2, 0.1, 0.9, 0.3,  //
      0.5, 0.0, -0.3, 1.1,  //
      0.0, 0.7, 0.4, -0.6,  //
      -0.8, 0.2, 0.1, 0.5;
  return 1e-4 * A;
}

Eigen::Matrix3Xd referencePositions() {
  Eigen::Matrix3Xd X(3, 2);
  X << 1e-3, 0.0, //
      1e-3, 1e-3, //
      0.0, 1e-3;
  return X;
}

// The goals are where the inputs `pull` would put the points, so the best inputs are known.
ControlDriverSetup setup(glossa::control::ControllerType type, const std::vector<double> &pull) {
  ControlDriverSetup s;
  s.parameters.type = type;
  s.parameters.pruning = false;
  s.groupNames = {"a", "b", "c", "d"};
  s.controlled = {0, 1, 2, 3};
  s.referencePositions = referencePositions();
  s.goals = s.referencePositions + LinearPlant(plantMatrix()).displacement(pull);
  s.weights = Eigen::Vector2d(1.0, 2.0);
  return s;
}

// Eq. 25 computed directly: sum_p w_p |X_p + d_p - xbar_p|.
double objectiveOf(const ControlDriverSetup &s, const std::vector<double> &inputs) {
  const Eigen::Matrix3Xd x = s.referencePositions + LinearPlant(plantMatrix()).displacement(inputs);
  double total = 0.0;
  for (Eigen::Index p = 0; p < x.cols(); ++p) total += s.weights(p) * (x.col(p) - s.goals.col(p)).norm();
  return total;
}

// Every binary input vector, ranked by eq. 25, best first (ties: the first enumerated).
std::vector<std::vector<double>> binaryInputsByObjective(const ControlDriverSetup &s) {
  std::vector<std::vector<double>> all;
  for (int bits = 0; bits < (1 << kGroups); ++bits) {
    std::vector<double> u(kGroups);
    for (int g = 0; g < kGroups; ++g) u[g] = (bits >> g) & 1 ? 1.0 : 0.0;
    all.push_back(u);
  }
  std::stable_sort(all.begin(), all.end(),
                   [&](const auto &a, const auto &b) { return objectiveOf(s, a) < objectiveOf(s, b); });
  return all;
}

const std::vector<double> kStretched(kGroups, 1.1); // every group in tension
} // namespace

TEST(ControlDriver, GeneticAlgorithmFindsTheBestBinaryInputs) {
  const auto s = setup(glossa::control::ControllerType::geneticAlgorithm, {0.9, 0.1, 0.8, 0.2});
  const auto ranked = binaryInputsByObjective(s);
  ASSERT_EQ(ranked[0], (std::vector<double>{1.0, 0.0, 1.0, 0.0})); // the goals were made so
  LinearPlant plant(plantMatrix());
  SingleControlGroup one;
  ControlDriver driver(s, plant, one);
  const ControlStepResult r = driver.step(0, kStretched);
  ASSERT_TRUE(r.found());
  EXPECT_EQ(r.inputs, ranked[0]);
  EXPECT_NEAR(r.objective, objectiveOf(s, ranked[0]), 1e-15);
  EXPECT_EQ(r.evaluated, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(r.candidates, static_cast<std::size_t>(plant.solves));
  EXPECT_EQ(plant.kept(), ranked[0]); // the winner's state is the one kept
  EXPECT_EQ(r.solve.newton.at(0).residualNorms, ranked[0]); // and so are its statistics
  // Per-point errors: the unweighted distances.
  const Eigen::Matrix3Xd x = s.referencePositions + plant.displacement(ranked[0]);
  ASSERT_EQ(r.pointErrors.size(), 2);
  for (Eigen::Index p = 0; p < 2; ++p) EXPECT_NEAR(r.pointErrors(p), (x.col(p) - s.goals.col(p)).norm(), 1e-18);
}

TEST(ControlDriver, AFailedCandidateIsNeverTheWinner) {
  const auto s = setup(glossa::control::ControllerType::geneticAlgorithm, {0.9, 0.1, 0.8, 0.2});
  const auto ranked = binaryInputsByObjective(s);
  LinearPlant plant(plantMatrix());
  plant.fails = [&](const std::vector<double> &u) { return u == ranked[0]; };
  SingleControlGroup one;
  ControlDriver driver(s, plant, one);
  const ControlStepResult r = driver.step(0, kStretched);
  ASSERT_TRUE(r.found());
  EXPECT_EQ(r.inputs, ranked[1]);
  EXPECT_EQ(plant.kept(), ranked[1]);
  EXPECT_NEAR(r.objective, objectiveOf(s, ranked[1]), 1e-15);

  // Nothing converges: nothing is found.
  LinearPlant failing(plantMatrix());
  failing.fails = [](const std::vector<double> &) { return true; };
  ControlDriver hopeless(s, failing, one);
  const ControlStepResult none = hopeless.step(0, kStretched);
  EXPECT_FALSE(none.found());
  EXPECT_GT(failing.solves, 0);
}

TEST(ControlDriver, PrunesAGroupInCompressionAndKeepsAnAlwaysEvaluatedOne) {
  auto s = setup(glossa::control::ControllerType::geneticAlgorithm, {0.9, 0.1, 0.8, 0.2});
  s.parameters.pruning = true;
  s.parameters.alwaysEvaluated = {"c"};
  LinearPlant plant(plantMatrix());
  SingleControlGroup one;
  ControlDriver driver(s, plant, one);
  // a stretched, b and c compressed (c always evaluated), d exactly at its reference (not above).
  const std::vector<double> stretch{1.02, 0.97, 0.95, 1.0};
  EXPECT_EQ(driver.evaluatedGroups(stretch), (std::vector<int>{0, 2}));
  const ControlStepResult r = driver.step(0, stretch);
  ASSERT_TRUE(r.found());
  EXPECT_EQ(r.evaluated, (std::vector<int>{0, 2}));
  EXPECT_EQ(r.inputs, (std::vector<double>{1.0, 0.0, 1.0, 0.0})); // the best over a and c
  EXPECT_EQ(r.candidates, 4u);                                    // 2^2 genomes, no more

  // The next step: a switched on, and now slack, stays searched (keep active groups).
  EXPECT_EQ(driver.evaluatedGroups({0.99, 0.97, 0.95, 1.0}), (std::vector<int>{0, 2}));
}

TEST(ControlDriver, GradientControllerReachesTheInputsThatHoldThePoints) {
  const std::vector<double> uStar{0.3, 0.6, 0.45, 0.15};
  auto s = setup(glossa::control::ControllerType::gradient, uStar);
  s.parameters.gradient.damping = 0.0;
  s.parameters.gradient.objectiveTolerance = 1e-12;
  LinearPlant plant(plantMatrix());
  SingleControlGroup one;
  ControlDriver driver(s, plant, one);
  const ControlStepResult r = driver.step(0, kStretched);
  ASSERT_TRUE(r.found());
  ASSERT_EQ(r.inputs.size(), uStar.size());
  for (std::size_t g = 0; g < uStar.size(); ++g) EXPECT_NEAR(r.inputs[g], uStar[g], 1e-9) << g;
  EXPECT_LT(r.objective, 1e-12);
  EXPECT_EQ(r.stop, "objective tolerance");
  EXPECT_EQ(r.sensitivities, 1); // a linear plant: one Gauss-Newton step from u = 0
  EXPECT_EQ(r.sensitivityKrylov, 4);
  EXPECT_EQ(r.candidates, 2u);
  EXPECT_EQ(plant.kept(), r.inputs);
}

TEST(ControlDriver, SensitivityCheckAgainstDifferencesOfSolves) {
  const std::vector<double> uStar{0.3, 0.6, 0.45, 0.15};
  auto s = setup(glossa::control::ControllerType::gradient, uStar);
  s.parameters.verifySensitivities = true;
  SingleControlGroup one;
  {
    LinearPlant plant(plantMatrix()); // exact sensitivities: differences of a linear plant agree
    ControlDriver driver(s, plant, one);
    const double check = driver.step(0, kStretched).sensitivityCheck;
    EXPECT_GE(check, 0.0);
    EXPECT_LT(check, 1e-9);
  }
  LinearPlant wrong(plantMatrix());
  wrong.sensitivityScale = 1.5; // S = 1.5 S_fd: max |S - S_fd| / max |S_fd| = 0.5
  ControlDriver driver(s, wrong, one);
  EXPECT_NEAR(driver.step(0, kStretched).sensitivityCheck, 0.5, 1e-9);
}
