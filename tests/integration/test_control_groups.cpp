// Control groups (--control-groups) on the control driver alone, under mpiexec -np 2: two groups of one
// rank, sharing every generation's candidates as they finish on a linear fake plant (LinearPlant.hpp),
// pick the same winner, bit for bit, as one group solving every candidate, step after step (seeded by
// the previous winner), and both groups end holding the winner's state; no candidate is solved twice.
#include <cstring>

#include <gtest/gtest.h>
#include <Teuchos_CommHelpers.hpp>

#include "LinearPlant.hpp"
#include "WorldComm.hpp"
#include "solvers/control/CommControlGroups.hpp"
#include "solvers/control/ControlDriver.hpp"

using namespace glossa;

namespace {
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

Eigen::MatrixXd plantMatrix() {
  Eigen::MatrixXd A(6, 5);
  A << 1.0, -0.5, 0.2, 0.0, 0.4, //
      0.3, 1.2, -0.4, 0.1, -0.2, //
      -0.2, 0.1, 0.9, 0.3, 0.6,  //
      0.5, 0.0, -0.3, 1.1, 0.1,  //
      0.0, 0.7, 0.4, -0.6, -0.9, //
      -0.8, 0.2, 0.1, 0.5, 0.3;
  return 1e-4 * A;
}

solvers::ControlDriverSetup gaSetup() {
  solvers::ControlDriverSetup s;
  s.parameters.type = control::ControllerType::geneticAlgorithm;
  s.parameters.ga.populationSize = 6; // 32 binary genomes: several generations, shared out
  s.parameters.ga.stagnationGenerations = 0;
  s.parameters.ga.generations = 4;
  s.groupNames = {"a", "b", "c", "d", "e"};
  s.controlled = {0, 1, 2, 3, 4};
  s.referencePositions = Eigen::Matrix3Xd::Zero(3, 2);
  s.goals = test::LinearPlant(plantMatrix()).displacement({0.9, 0.1, 0.8, 0.2, 0.6});
  s.weights = Eigen::Vector2d(1.0, 0.5);
  return s;
}
} // namespace

TEST(ControlGroups, TwoGroupsPickTheWinnerOfOne) {
  const auto world = test::worldComm();
  ASSERT_EQ(world->getSize(), 2) << "run under mpiexec -np 2";
  const solvers::CommControlGroups two(world, 2);
  ASSERT_EQ(two.groupComm()->getSize(), 1);
  const solvers::SingleControlGroup one;
  test::LinearPlant sharedPlant(plantMatrix()), alonePlant(plantMatrix());
  // Some candidates fail, among them one the search meets (all but b on).
  auto fails = [](const std::vector<double> &u) { return u == std::vector<double>{1.0, 0.0, 1.0, 1.0, 1.0}; };
  sharedPlant.fails = alonePlant.fails = fails;
  solvers::ControlDriver shared(gaSetup(), sharedPlant, two), alone(gaSetup(), alonePlant, one);

  // Stretches that change the searched groups from step to step.
  const std::vector<std::vector<double>> stretches{
      {1.1, 1.1, 1.1, 1.1, 1.1}, {1.1, 0.9, 1.1, 1.1, 0.9}, {0.9, 1.1, 1.1, 1.1, 1.1}};
  for (std::size_t k = 0; k < stretches.size(); ++k) {
    const auto a = alone.step(static_cast<int>(k), stretches[k]);
    const auto b = shared.step(static_cast<int>(k), stretches[k]);
    ASSERT_TRUE(a.found()) << k;
    ASSERT_TRUE(b.found()) << k;
    EXPECT_EQ(b.inputs, a.inputs) << k;
    EXPECT_EQ(b.evaluated, a.evaluated) << k;
    EXPECT_TRUE(sameBits(b.objective, a.objective)) << k;
    EXPECT_EQ(b.candidates, a.candidates) << k;
    EXPECT_EQ(b.generations, a.generations) << k;
    EXPECT_EQ(b.stop, a.stop) << k;
    ASSERT_EQ(b.pointErrors.size(), a.pointErrors.size()) << k;
    for (Eigen::Index p = 0; p < a.pointErrors.size(); ++p) EXPECT_TRUE(sameBits(b.pointErrors(p), a.pointErrors(p))) << k;
    EXPECT_EQ(b.solve.newton.at(0).residualNorms, a.inputs) << k; // the winner's statistics
    EXPECT_EQ(sharedPlant.kept(), a.inputs) << k;                  // and its state, in both groups
  }
  // Between them the groups solved every candidate once. Which group took how many depends on
  // which finished first (the fake plant's solves take microseconds, so one group may take nearly
  // all): the sharing itself is checked in CommControlGroups.ABusyGroupLeavesTheBatchToTheOther.
  int total = 0;
  Teuchos::reduceAll(*world, Teuchos::REDUCE_SUM, sharedPlant.solves, Teuchos::outArg(total));
  EXPECT_EQ(total, alonePlant.solves);
}
