// The control driver on a linear fake plant (LinearPlant.hpp: d = A u), without a deck or a
// solve: the GA's winner against the brute-force optimum over the binary inputs, the gradient
// controller against the inputs that put the points on their goals, pruning, failed candidates,
// and the finite-difference check of the sensitivities.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include <Eigen/Cholesky>

#include "LinearPlant.hpp"
#include "solvers/control/ControlDriver.hpp"

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

// Every binary input vector, ranked by `value`, best first (ties: the first enumerated).
std::vector<std::vector<double>> binaryInputsBy(const std::function<double(const std::vector<double> &)> &value) {
  std::vector<std::vector<double>> all;
  for (int bits = 0; bits < (1 << kGroups); ++bits) {
    std::vector<double> u(kGroups);
    for (int g = 0; g < kGroups; ++g) u[g] = (bits >> g) & 1 ? 1.0 : 0.0;
    all.push_back(u);
  }
  std::stable_sort(all.begin(), all.end(), [&](const auto &a, const auto &b) { return value(a) < value(b); });
  return all;
}

// Ranked by eq. 25.
std::vector<std::vector<double>> binaryInputsByObjective(const ControlDriverSetup &s) {
  return binaryInputsBy([&s](const std::vector<double> &u) { return objectiveOf(s, u); });
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
  // The failed solves are counted, with the plant's reason: one per solve of the failing inputs.
  const auto failedSolves = std::count(plant.solved.begin(), plant.solved.end(), ranked[0]);
  EXPECT_GT(failedSolves, 0);
  EXPECT_EQ(r.failedCandidates, static_cast<std::size_t>(failedSolves));
  EXPECT_EQ(r.firstFailure, "the fake solve failed");

  // Nothing converges: nothing is found.
  LinearPlant failing(plantMatrix());
  failing.fails = [](const std::vector<double> &) { return true; };
  ControlDriver hopeless(s, failing, one);
  const ControlStepResult none = hopeless.step(0, kStretched);
  EXPECT_FALSE(none.found());
  EXPECT_GT(failing.solves, 0);
  EXPECT_EQ(none.failedCandidates, static_cast<std::size_t>(failing.solves));

  // Screened candidates are failed ones, counted apart: here every solve but those of the best
  // inputs fails, and those with the first group on are screened.
  LinearPlant screening(plantMatrix());
  screening.fails = [&](const std::vector<double> &u) { return u != ranked[0]; };
  screening.screens = [](const std::vector<double> &u) { return u[0] > 0.5; };
  ControlDriver screened(s, screening, one);
  const ControlStepResult sr = screened.step(0, kStretched);
  ASSERT_TRUE(sr.found());
  EXPECT_EQ(sr.inputs, ranked[0]);
  const auto screenedSolves = std::count_if(screening.solved.begin(), screening.solved.end(),
                                            [&](const auto &u) { return u != ranked[0] && u[0] > 0.5; });
  const auto bestSolves = std::count(screening.solved.begin(), screening.solved.end(), ranked[0]);
  EXPECT_GT(screenedSolves, 0);
  EXPECT_EQ(sr.screenedCandidates, static_cast<std::size_t>(screenedSolves));
  EXPECT_EQ(sr.failedCandidates, static_cast<std::size_t>(screening.solves - bestSolves));
  EXPECT_EQ(r.screenedCandidates, 0u);
  EXPECT_EQ(r.solvedAgainCandidates, 0u);

  // Candidates solved twice (a moved start that failed, then the step's start) are counted, the
  // failed and the converged alike.
  LinearPlant twice(plantMatrix());
  twice.fails = [&](const std::vector<double> &u) { return u == ranked[1]; };
  twice.solvesAgain = [&](const std::vector<double> &u) { return u == ranked[0] || u == ranked[1]; };
  ControlDriver again(s, twice, one);
  const ControlStepResult ar = again.step(0, kStretched);
  const auto solvedTwice = std::count_if(twice.solved.begin(), twice.solved.end(),
                                         [&](const auto &u) { return u == ranked[0] || u == ranked[1]; });
  EXPECT_GT(std::count(twice.solved.begin(), twice.solved.end(), ranked[1]), 0);
  EXPECT_EQ(ar.solvedAgainCandidates, static_cast<std::size_t>(solvedTwice));

  // The gradient controller counts its failed solves too.
  const auto g = setup(glossa::control::ControllerType::gradient, {0.9, 0.1, 0.8, 0.2});
  LinearPlant failingGradient(plantMatrix());
  failingGradient.fails = [](const std::vector<double> &) { return true; };
  failingGradient.solvesAgain = [](const std::vector<double> &) { return true; };
  ControlDriver gradient(g, failingGradient, one);
  const ControlStepResult gr = gradient.step(0, kStretched);
  EXPECT_FALSE(gr.found());
  EXPECT_EQ(gr.failedCandidates, static_cast<std::size_t>(failingGradient.solves));
  EXPECT_EQ(gr.solvedAgainCandidates, static_cast<std::size_t>(failingGradient.solves));
  EXPECT_EQ(gr.firstFailure, "the fake solve failed");
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

// Effort (ControllerParameters::effortWeight): with two muscles that move the points alike, eq. 25
// has a valley of minimisers (u_a + u_b = const); the price of activation picks the one with the
// least sum of squares. The gradient controller's minimiser of |A u - g|^2 + eps^2 |u|^2 on a
// linear plant is the ridge solution (A^T A + eps^2 I)^-1 A^T g, reached in one Gauss-Newton step.
TEST(ControlDriver, EffortWeightPicksTheLeastActivationAmongRedundantMuscles) {
  Eigen::MatrixXd A = plantMatrix();
  A.col(1) = A.col(0); // a and b redundant
  const std::vector<double> pull{0.5, 0.3, 0.45, 0.15};
  auto s = setup(glossa::control::ControllerType::gradient, pull);
  s.goals = s.referencePositions + LinearPlant(A).displacement(pull);
  s.parameters.gradient.damping = 0.0;
  s.parameters.effortWeight = 1e-6; // 1 um per unit input, against offsets of about 0.1 mm
  const Eigen::Matrix3Xd g = s.goals - s.referencePositions;
  Eigen::VectorXd b = Eigen::Map<const Eigen::VectorXd>(g.data(), g.size());
  Eigen::MatrixXd WA = A; // the residual is weighted per point: W (A u - g)
  for (Eigen::Index p = 0; p < 2; ++p) {
    WA.middleRows<3>(3 * p) *= s.weights(p);
    b.segment<3>(3 * p) *= s.weights(p);
  }
  const double e2 = s.parameters.effortWeight * s.parameters.effortWeight;
  const Eigen::VectorXd ridge =
      (WA.transpose() * WA + e2 * Eigen::MatrixXd::Identity(kGroups, kGroups)).ldlt().solve(WA.transpose() * b);
  ASSERT_NEAR(ridge(0), ridge(1), 1e-9); // the split is even: a and b share the pull of 0.8
  ASSERT_NEAR(ridge(0), 0.4, 1e-3);
  LinearPlant plant(A);
  SingleControlGroup one;
  ControlDriver driver(s, plant, one);
  const ControlStepResult r = driver.step(0, kStretched);
  ASSERT_TRUE(r.found());
  for (Eigen::Index m = 0; m < kGroups; ++m) EXPECT_NEAR(r.inputs[m], ridge(m), 1e-9) << m;
  // eq. 25 is reported without the effort.
  const Eigen::Matrix3Xd x = s.referencePositions + plant.displacement(r.inputs);
  double eq25 = 0.0;
  for (Eigen::Index p = 0; p < x.cols(); ++p) eq25 += s.weights(p) * (x.col(p) - s.goals.col(p)).norm();
  EXPECT_NEAR(r.objective, eq25, 1e-15);
}

// The GA ranks by eq. 25 + eps sum u^2: its winner is the brute-force best of that sum over the
// binary inputs, here not the best of eq. 25 alone.
TEST(ControlDriver, GeneticAlgorithmRanksByObjectivePlusEffort) {
  auto s = setup(glossa::control::ControllerType::geneticAlgorithm, {0.9, 0.1, 0.8, 0.2});
  s.parameters.effortWeight = 1e-4;
  const auto byObjective = binaryInputsByObjective(s);
  auto fitness = [&](const std::vector<double> &u) {
    double sum = 0.0;
    for (double v : u) sum += v * v;
    return objectiveOf(s, u) + s.parameters.effortWeight * sum;
  };
  const auto byFitness = binaryInputsBy(fitness);
  ASSERT_NE(byFitness[0], byObjective[0]); // the effort changes the winner
  LinearPlant plant(plantMatrix());
  SingleControlGroup one;
  ControlDriver driver(s, plant, one);
  const ControlStepResult r = driver.step(0, kStretched);
  ASSERT_TRUE(r.found());
  EXPECT_EQ(r.inputs, byFitness[0]);
  EXPECT_EQ(plant.kept(), byFitness[0]);
  EXPECT_NEAR(r.objective, objectiveOf(s, byFitness[0]), 1e-15); // reported: eq. 25 alone
}

// The airway term (ControllerParameters::airwayWeight): w_A max(0, A_open - A(u)) joins eq. 25.
// On a linear plant with an affine smallest area below A_open at the optimum, the gradient
// controller minimises |W (A u - g)|^2 + w_A^2 (A_open - a0 - c u)^2: a linear least-squares
// problem, whose solution it reaches; the lumen ends wider than at the points' own optimum.
TEST(ControlDriver, GradientControllerTradesThePointsForTheAirwayTerm) {
  const std::vector<double> uStar{0.3, 0.6, 0.45, 0.15};
  auto s = setup(glossa::control::ControllerType::gradient, uStar);
  s.parameters.gradient.damping = 0.0;
  s.parameters.airwayWeight = 20.0;     // 1/m: 4 mm^2 short costs 0.08 mm, like the points' offsets
  s.parameters.airwayOpenArea = 16e-6;  // m^2
  LinearPlant plant(plantMatrix());
  plant.area0 = 10e-6;
  plant.areaRate = Eigen::RowVector4d(4e-6, -2e-6, 3e-6, 5e-6);
  ASSERT_LT(plant.area(uStar), s.parameters.airwayOpenArea);
  // The least-squares solution, stacked: the weighted points, then the airway row.
  Eigen::MatrixXd M(7, kGroups);
  Eigen::VectorXd y(7);
  M.topRows(6) = plantMatrix();
  const Eigen::Matrix3Xd g = s.goals - s.referencePositions;
  y.head(6) = Eigen::Map<const Eigen::VectorXd>(g.data(), 6);
  for (Eigen::Index p = 0; p < 2; ++p) {
    M.middleRows<3>(3 * p) *= s.weights(p);
    y.segment<3>(3 * p) *= s.weights(p);
  }
  M.row(6) = s.parameters.airwayWeight * plant.areaRate;
  y(6) = s.parameters.airwayWeight * (s.parameters.airwayOpenArea - plant.area0);
  const Eigen::VectorXd best = (M.transpose() * M).ldlt().solve(M.transpose() * y);
  const std::vector<double> bestInputs(best.data(), best.data() + kGroups);
  for (double u : bestInputs) ASSERT_TRUE(u > 0.0 && u < 1.0) << u;  // inside the bounds
  ASSERT_LT(plant.area(bestInputs), s.parameters.airwayOpenArea);     // the term still active there
  SingleControlGroup one;
  ControlDriver driver(s, plant, one);
  const ControlStepResult r = driver.step(0, kStretched);
  ASSERT_TRUE(r.found());
  for (std::size_t m = 0; m < bestInputs.size(); ++m) EXPECT_NEAR(r.inputs[m], bestInputs[m], 1e-9) << m;
  EXPECT_GT(plant.area(r.inputs), plant.area(uStar) + 1e-6); // wider than the points alone would leave it
  // The objective reported is eq. 25 plus the airway term.
  EXPECT_NEAR(r.objective,
              objectiveOf(s, r.inputs) + s.parameters.airwayWeight * (s.parameters.airwayOpenArea - plant.area(r.inputs)),
              1e-15);
}

// Above A_open the term costs nothing: the points' own optimum is reached as without it.
TEST(ControlDriver, AnOpenAirwayLeavesTheGradientControllerAlone) {
  const std::vector<double> uStar{0.3, 0.6, 0.45, 0.15};
  auto s = setup(glossa::control::ControllerType::gradient, uStar);
  s.parameters.gradient.damping = 0.0;
  s.parameters.gradient.objectiveTolerance = 1e-12;
  s.parameters.airwayWeight = 50.0;
  s.parameters.airwayOpenArea = 5e-6;
  LinearPlant plant(plantMatrix());
  plant.area0 = 10e-6;
  plant.areaRate = Eigen::RowVector4d(4e-6, -2e-6, 3e-6, 5e-6);
  SingleControlGroup one;
  ControlDriver driver(s, plant, one);
  const ControlStepResult r = driver.step(0, kStretched);
  ASSERT_TRUE(r.found());
  for (std::size_t g = 0; g < uStar.size(); ++g) EXPECT_NEAR(r.inputs[g], uStar[g], 1e-9) << g;
  EXPECT_LT(r.objective, 1e-12);
}

// The GA ranks by eq. 25 plus the airway term: its winner is the brute-force best of that sum over
// the binary inputs; here only d opens the lumen, and the term outweighs eq. 25's best without it.
TEST(ControlDriver, GeneticAlgorithmRanksWithTheAirwayTerm) {
  auto s = setup(glossa::control::ControllerType::geneticAlgorithm, {0.9, 0.1, 0.8, 0.2});
  s.parameters.airwayWeight = 1e3;
  s.parameters.airwayOpenArea = 18e-6;
  LinearPlant plant(plantMatrix());
  plant.area0 = 10e-6;
  plant.areaRate = Eigen::RowVector4d(0.0, 0.0, 0.0, 8e-6);
  const auto byObjective = binaryInputsByObjective(s);
  auto fitness = [&](const std::vector<double> &u) {
    return objectiveOf(s, u) + s.parameters.airwayWeight * std::max(0.0, s.parameters.airwayOpenArea - plant.area(u));
  };
  const auto byFitness = binaryInputsBy(fitness);
  ASSERT_EQ(byObjective[0][3], 0.0);  // eq. 25 alone leaves d off
  ASSERT_EQ(byFitness[0][3], 1.0);    // the airway term turns it on
  SingleControlGroup one;
  ControlDriver driver(s, plant, one);
  const ControlStepResult r = driver.step(0, kStretched);
  ASSERT_TRUE(r.found());
  EXPECT_EQ(r.inputs, byFitness[0]);
  EXPECT_EQ(plant.kept(), byFitness[0]);
  EXPECT_NEAR(r.objective, fitness(byFitness[0]), 1e-15);
}

// With the airway term the sensitivity check covers dA/du too, against its own scale.
TEST(ControlDriver, SensitivityCheckCoversTheSmallestArea) {
  const std::vector<double> uStar{0.3, 0.6, 0.45, 0.15};
  auto s = setup(glossa::control::ControllerType::gradient, uStar);
  s.parameters.verifySensitivities = true;
  s.parameters.airwayWeight = 50.0;
  s.parameters.airwayOpenArea = 20e-6;
  SingleControlGroup one;
  for (double scale : {1.0, 1.5}) {
    LinearPlant plant(plantMatrix());
    plant.area0 = 10e-6;
    plant.areaRate = Eigen::RowVector4d(4e-6, -2e-6, 3e-6, 5e-6);
    plant.areaSensitivityScale = scale; // 1.5: max |dA/du - FD| / max |FD| = 0.5
    ControlDriver driver(s, plant, one);
    EXPECT_NEAR(driver.step(0, kStretched).sensitivityCheck, scale - 1.0, 1e-9) << scale;
  }
}

// Seed with prediction: from the third step on, generation 0 holds 2 u_{k-1} - u_{k-2} (clipped).
TEST(ControlDriver, GeneticAlgorithmSeedsTheLinearPrediction) {
  auto s = setup(glossa::control::ControllerType::geneticAlgorithm, {0.9, 0.1, 0.8, 0.2});
  s.parameters.ga.geneType = glossa::control::GeneType::continuous;
  s.parameters.ga.generations = 3;
  s.parameters.ga.populationSize = 10;
  s.parameters.predictionSeed = glossa::control::PredictionSeed::extrapolation;
  LinearPlant plant(plantMatrix());
  SingleControlGroup one;
  ControlDriver driver(s, plant, one);
  const auto first = driver.step(0, kStretched).inputs;
  const auto second = driver.step(1, kStretched).inputs;
  std::vector<double> prediction(kGroups);
  for (int m = 0; m < kGroups; ++m) prediction[m] = std::clamp(2.0 * second[m] - first[m], 0.0, 1.0);
  ASSERT_NE(prediction, second); // the two steps differ, so the prediction is a genome of its own
  const std::size_t before = plant.solved.size();
  driver.step(2, kStretched);
  // Generation 0 is solved first: the previous best, then the prediction.
  ASSERT_GE(plant.solved.size(), before + 2);
  EXPECT_EQ(plant.solved[before], second);
  for (int m = 0; m < kGroups; ++m) EXPECT_NEAR(plant.solved[before + 1][m], prediction[m], 1e-15) << m;

  // Without it, the second genome solved is a corner (all off).
  s.parameters.predictionSeed = glossa::control::PredictionSeed::none;
  LinearPlant plain(plantMatrix());
  ControlDriver without(s, plain, one);
  without.step(0, kStretched);
  without.step(1, kStretched);
  const std::size_t at = plain.solved.size();
  without.step(2, kStretched);
  EXPECT_EQ(plain.solved[at + 1], std::vector<double>(kGroups, 0.0));
}

// Gauss-Newton step seed: on a linear plant one bounded linearised step from the previous best is
// exact, so generation 0 alone (generations = 1) already holds the inputs that put the points on
// their goals; without the seed it does not. One solve and one sensitivity more per step.
TEST(ControlDriver, GeneticAlgorithmSeedsAGaussNewtonStep) {
  const std::vector<double> uStar{0.3, 0.6, 0.45, 0.15};
  auto s = setup(glossa::control::ControllerType::geneticAlgorithm, uStar);
  s.parameters.ga.geneType = glossa::control::GeneType::continuous;
  s.parameters.ga.generations = 1;
  s.parameters.ga.populationSize = 8;
  s.parameters.gradient.damping = 0.0;
  s.parameters.predictionSeed = glossa::control::PredictionSeed::gaussNewtonStep;
  SingleControlGroup one;
  LinearPlant plant(plantMatrix());
  ControlDriver driver(s, plant, one);
  const ControlStepResult r = driver.step(0, kStretched);
  ASSERT_TRUE(r.found());
  for (int m = 0; m < kGroups; ++m) EXPECT_NEAR(r.inputs[m], uStar[m], 1e-9) << m;
  EXPECT_LT(r.objective, 1e-12);
  EXPECT_EQ(r.sensitivities, 1);
  EXPECT_EQ(r.candidates, static_cast<std::size_t>(plant.solves)); // the prediction's solve counted
  EXPECT_EQ(plant.kept(), r.inputs);

  s.parameters.predictionSeed = glossa::control::PredictionSeed::none;
  LinearPlant plain(plantMatrix());
  ControlDriver without(s, plain, one);
  EXPECT_GT(without.step(0, kStretched).objective, 1e-6);
}

// Gauss-Newton step seeds at several step lengths: generation 0 holds u + t du for t = 1, 1/2,
// 1/4 (a line search along the linearised step), solved right after the prediction's own solve.
TEST(ControlDriver, GeneticAlgorithmSeedsTheGaussNewtonStepAtShorterLengths) {
  const std::vector<double> uStar{0.3, 0.6, 0.45, 0.15};
  auto s = setup(glossa::control::ControllerType::geneticAlgorithm, uStar);
  s.parameters.ga.geneType = glossa::control::GeneType::continuous;
  s.parameters.ga.generations = 1;
  s.parameters.ga.populationSize = 8;
  s.parameters.gradient.damping = 0.0;
  s.parameters.predictionSeed = glossa::control::PredictionSeed::gaussNewtonStep;
  s.parameters.predictionSeedSteps = 3;
  SingleControlGroup one;
  LinearPlant plant(plantMatrix());
  ControlDriver driver(s, plant, one);
  const ControlStepResult r = driver.step(0, kStretched);
  ASSERT_TRUE(r.found());
  // From u = 0 the linearised step is u* itself (the plant is linear).
  ASSERT_GE(plant.solved.size(), 4u);
  EXPECT_EQ(plant.solved[0], std::vector<double>(kGroups, 0.0));
  double t = 1.0;
  for (std::size_t k = 1; k <= 3; ++k, t *= 0.5)
    for (int m = 0; m < kGroups; ++m) EXPECT_NEAR(plant.solved[k][m], t * uStar[m], 1e-9) << k << ' ' << m;
  for (int m = 0; m < kGroups; ++m) EXPECT_NEAR(r.inputs[m], uStar[m], 1e-9) << m;

  s.parameters.predictionSeedSteps = 0;
  EXPECT_THROW(s.parameters.validate(), std::invalid_argument);
}

// The previous best is solved once per step: the Gauss-Newton seed linearises about it, and
// generation 0, which holds it again, takes its value from that solve. The count of candidates
// is that of the solves.
TEST(ControlDriver, ThePreviousBestIsSolvedOncePerStep) {
  auto s = setup(glossa::control::ControllerType::geneticAlgorithm, {0.3, 0.6, 0.45, 0.15});
  s.parameters.ga.geneType = glossa::control::GeneType::continuous;
  s.parameters.ga.generations = 2;
  s.parameters.ga.populationSize = 8;
  s.parameters.predictionSeed = glossa::control::PredictionSeed::gaussNewtonStep;
  SingleControlGroup one;
  LinearPlant plant(plantMatrix());
  ControlDriver driver(s, plant, one);
  const auto first = driver.step(0, kStretched);
  const int before = plant.solves;
  const auto second = driver.step(1, kStretched);
  ASSERT_TRUE(second.found());
  const std::vector<std::vector<double>> solved(plant.solved.begin() + before, plant.solved.end());
  EXPECT_EQ(solved.front(), first.inputs); // the seed's own solve
  EXPECT_EQ(std::count(solved.begin(), solved.end(), first.inputs), 1);
  EXPECT_EQ(second.candidates, static_cast<std::size_t>(plant.solves - before));
  EXPECT_LE(second.objective, first.objective + 1e-15); // the previous best still competes
}

// A sensitivity that cannot be computed (its tangent solve did not converge) stops the search at
// the inputs it has instead of the run: the gradient controller keeps its start, solved; the GA
// goes on without its Gauss-Newton seed's prediction, as without the seed.
TEST(ControlDriver, AFailedSensitivityStopsTheSearchNotTheRun) {
  const std::vector<double> uStar{0.3, 0.6, 0.45, 0.15};
  auto s = setup(glossa::control::ControllerType::gradient, uStar);
  LinearPlant plant(plantMatrix());
  plant.sensitivityFailure = "tangent solve did not converge";
  SingleControlGroup one;
  ControlDriver driver(s, plant, one);
  const ControlStepResult r = driver.step(0, kStretched);
  ASSERT_TRUE(r.found());
  EXPECT_EQ(r.stop, "sensitivity failed");
  EXPECT_EQ(r.inputs, std::vector<double>(kGroups, 0.0)); // the start, the previous step's inputs
  EXPECT_NEAR(r.objective, objectiveOf(s, r.inputs), 1e-15);
  EXPECT_EQ(r.candidates, 1u);

  auto g = setup(glossa::control::ControllerType::geneticAlgorithm, uStar);
  g.parameters.ga.geneType = glossa::control::GeneType::continuous;
  g.parameters.ga.generations = 3;
  g.parameters.ga.populationSize = 8;
  g.parameters.predictionSeed = glossa::control::PredictionSeed::gaussNewtonStep;
  LinearPlant failing(plantMatrix());
  failing.sensitivityFailure = "tangent solve did not converge";
  ControlDriver ga(g, failing, one);
  const ControlStepResult seeded = ga.step(0, kStretched);
  ASSERT_TRUE(seeded.found());
  EXPECT_NEAR(seeded.objective, objectiveOf(g, seeded.inputs), 1e-15);
  EXPECT_EQ(seeded.candidates, static_cast<std::size_t>(failing.solves));
}
