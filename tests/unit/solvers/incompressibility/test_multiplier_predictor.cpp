// Where a step's multipliers start (solvers/incompressibility/MultiplierPredictor): the last step's next update,
// extrapolated linearly in time, which is exact for multipliers linear in time whatever the steps.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "solvers/incompressibility/MultiplierPredictor.hpp"

using glossa::solvers::MultiplierPredictor;

namespace {
// Lambda*(t) = a_e + b_e t per element.
std::vector<double> linearInTime(double t) { return {1.0 + 2.0 * t, -3.0 + 0.5 * t, 4.0 - 7.0 * t}; }
// Where a step of length dt starts whose committed multipliers are `lambda`.
std::vector<double> predicted(const MultiplierPredictor &p, double dt, std::vector<double> lambda) {
  p.predict(dt, lambda);
  return lambda;
}
} // namespace

TEST(MultiplierPredictor, LeavesTheCommittedMultipliersUntilAStepHasBeenCommitted) {
  EXPECT_EQ(predicted(MultiplierPredictor{}, 0.1, {1.0, 2.0, 3.0}), (std::vector<double>{1.0, 2.0, 3.0}));
}

TEST(MultiplierPredictor, StartsFromTheNextUpdateAfterOneStep) {
  MultiplierPredictor p;
  p.commit(linearInTime(0.2), 0.2);
  EXPECT_EQ(predicted(p, 0.1, std::vector<double>(3, 0.0)), linearInTime(0.2));
}

TEST(MultiplierPredictor, ExtrapolationIsExactForMultipliersLinearInTimeWithUnequalSteps) {
  MultiplierPredictor p;
  p.commit(linearInTime(0.3), 0.3);
  p.commit(linearInTime(0.5), 0.2);
  std::vector<double> lambda(3, 0.0);
  p.predict(0.05, lambda); // a cut-back step: half of a quarter of the last
  const std::vector<double> exact = linearInTime(0.55);
  for (std::size_t e = 0; e < exact.size(); ++e) EXPECT_NEAR(lambda[e], exact[e], 1e-14);
}

TEST(MultiplierPredictor, AStepWithoutMultipliersStopsThePrediction) {
  MultiplierPredictor p;
  p.commit(linearInTime(0.1), 0.1);
  p.commit({}, 0.1); // e.g. a point of an arc-length path
  EXPECT_EQ(predicted(p, 0.1, {5.0, 6.0, 7.0}), (std::vector<double>{5.0, 6.0, 7.0}));
}

TEST(MultiplierPredictor, ACheckpointRestoresThePredictionAndRefusesAnotherMesh) {
  MultiplierPredictor p;
  p.commit(linearInTime(0.1), 0.1);
  p.commit(linearInTime(0.2), 0.1);
  MultiplierPredictor restored;
  restored.restore(p.toJson(), 3);
  EXPECT_EQ(predicted(restored, 0.1, std::vector<double>(3, 0.0)), predicted(p, 0.1, std::vector<double>(3, 0.0)));
  EXPECT_THROW(restored.restore(p.toJson(), 4), std::invalid_argument);
}
