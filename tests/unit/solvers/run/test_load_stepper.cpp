// The load stepper on a fake step solve (no deck, no assembly): steps to the end time, a failed
// attempt leaves the committed state intact and cuts the step back, the linear predictor starts
// a step at the exact extrapolation of a motion linear in time, a failure from the extrapolated
// start is retried once from the committed state (not when the step is past a limit point), a
// checkpoint's save and restore continue the same steps, and (under mpiexec on 2 ranks) a step
// that fails or is past a limit point on one rank only fails on every rank, for that rank's reason.
#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "solvers/run/LoadStepper.hpp"

using namespace glossa;
using namespace glossa::solvers;

namespace {
constexpr std::size_t kElements = 3;

Teuchos::RCP<const assembly::Map> stepperMap() {
  static const auto m = Teuchos::rcp(new assembly::Map(8, 0, Tpetra::getDefaultComm()));
  return m;
}

// The exact state of the fake problem at time t: u_i = (i + 1) t, Lambda_e = 10 (e + 1) t, linear in t.
double exactU(std::size_t gid, double t) { return (static_cast<double>(gid) + 1.0) * t; }
double exactLambda(std::size_t e, double t) { return 10.0 * (static_cast<double>(e) + 1.0) * t; }

StepState stateAt(double t) {
  StepState s(stepperMap(), kElements);
  auto data = s.u.getDataNonConst();
  for (long i = 0; i < data.size(); ++i)
    data[i] = exactU(stepperMap()->getGlobalElement(static_cast<int>(i)), t);
  for (std::size_t e = 0; e < kElements; ++e) s.lambda[e] = exactLambda(e, t);
  return s;
}

// How far a state is from the exact one at t (largest difference).
double distance(const StepState &s, double t) {
  const StepState exact = stateAt(t);
  assembly::Vector d(s.u, Teuchos::Copy);
  d.update(-1.0, exact.u, 1.0);
  double worst = d.normInf();
  for (std::size_t e = 0; e < kElements; ++e) worst = std::max(worst, std::abs(s.lambda[e] - exact.lambda[e]));
  return worst;
}

// A step solve that lands on the exact state unless `fails` says otherwise; it records where
// each attempt started.
class FakeSolve final : public StepAttempter {
public:
  std::function<bool(const StepTrial &, double startDistance)> fails = [](const StepTrial &, double) { return false; };
  bool unstable = false;
  std::vector<double> startDistances; // of each attempt's start from the exact state at its time
  int attempts = 0;

  void attempt(StepTrial &trial) override {
    ++attempts;
    const double d = distance(trial.state, trial.time);
    startDistances.push_back(d);
    if (fails(trial, d)) {
      trial.attempt.ok = false;
      trial.attempt.unstable = unstable;
      trial.attempt.why = "fake failure";
      return;
    }
    trial.state.assign(stateAt(trial.time));
    trial.attempt.ok = true;
  }
};

// Steps to the end; returns the number of committed steps.
int runToEnd(LoadStepper &stepper, FakeSolve &solve, int *retries = nullptr) {
  int steps = 0;
  while (!stepper.finished()) {
    if (stepper.attemptStep(solve, 0.0, [retries](const StepTrial &) { if (retries) ++*retries; })) {
      stepper.commit({});
      ++steps;
    } else if (!stepper.cutBack()) {
      break;
    }
  }
  return steps;
}
} // namespace

TEST(LoadStepper, StepsToTheEndTimeAndCommitsEachConvergedTrial) {
  LoadStepper stepper({1.0, 0.25, 1e-3}, false, stateAt(0.0));
  FakeSolve solve;
  EXPECT_EQ(runToEnd(stepper, solve), 4);
  EXPECT_TRUE(stepper.finished());
  EXPECT_DOUBLE_EQ(stepper.time(), 1.0);
  EXPECT_EQ(stepper.stepNumber(), 4);
  EXPECT_LT(distance(stepper.committed(), 1.0), 1e-14);
}

TEST(LoadStepper, AFailedAttemptLeavesTheCommittedStateAndCutsTheStepBack) {
  LoadStepper stepper({1.0, 0.25, 1e-3}, false, stateAt(0.0));
  FakeSolve solve;
  solve.fails = [](const StepTrial &trial, double) { return trial.dt > 0.1; };
  EXPECT_FALSE(stepper.attemptStep(solve, 0.0, {}));
  EXPECT_DOUBLE_EQ(stepper.time(), 0.0);
  EXPECT_EQ(stepper.stepNumber(), 0);
  EXPECT_LT(distance(stepper.committed(), 0.0), 1e-14); // untouched by the failed trial
  EXPECT_TRUE(stepper.cutBack());
  EXPECT_DOUBLE_EQ(stepper.steps().stepSize(), 0.125);
  runToEnd(stepper, solve);
  EXPECT_DOUBLE_EQ(stepper.time(), 1.0);
}

TEST(LoadStepper, BelowTheMinimumStepItStops) {
  LoadStepper stepper({1.0, 0.25, 0.1}, false, stateAt(0.0));
  FakeSolve solve;
  solve.fails = [](const StepTrial &, double) { return true; };
  EXPECT_EQ(runToEnd(stepper, solve), 0);
  EXPECT_FALSE(stepper.finished());
  EXPECT_EQ(solve.attempts, 2); // 0.25, 0.125; 0.0625 would be below 0.1
}

TEST(LoadStepper, WithoutThePredictorEveryStepStartsFromTheCommittedState) {
  LoadStepper stepper({1.0, 0.25, 1e-3}, false, stateAt(0.0));
  FakeSolve solve;
  runToEnd(stepper, solve);
  // The committed state at t - dt is 0.25 away in time: its distance is that of a step's motion.
  ASSERT_EQ(solve.startDistances.size(), 4u);
  for (double d : solve.startDistances) EXPECT_NEAR(d, exactLambda(kElements - 1, 0.25), 1e-12);
}

TEST(LoadStepper, TheLinearPredictorStartsAtTheExtrapolationOfALinearMotion) {
  LoadStepper stepper({1.0, 0.25, 1e-3}, true, stateAt(0.0));
  FakeSolve solve;
  runToEnd(stepper, solve);
  ASSERT_EQ(solve.startDistances.size(), 4u);
  // The first step has no step before it; from the second on the extrapolation is exact.
  EXPECT_GT(solve.startDistances[0], 1.0);
  for (std::size_t k = 1; k < 4; ++k) EXPECT_LT(solve.startDistances[k], 1e-13) << "step " << k + 1;
}

TEST(LoadStepper, AFailureFromTheExtrapolatedStartIsRetriedFromTheCommittedState) {
  LoadStepper stepper({1.0, 0.25, 1e-3}, true, stateAt(0.0));
  FakeSolve solve;
  // Fails from every extrapolated start (the only starts at distance < 1e-13 here).
  solve.fails = [](const StepTrial &, double startDistance) { return startDistance < 1e-13; };
  int retries = 0;
  EXPECT_EQ(runToEnd(stepper, solve, &retries), 4);
  EXPECT_EQ(retries, 3);
  EXPECT_EQ(solve.attempts, 7);
  EXPECT_DOUBLE_EQ(stepper.steps().stepSize(), 0.25); // a retry is not a cut-back
}

TEST(LoadStepper, AStepPastALimitPointIsNotRetried) {
  LoadStepper stepper({1.0, 0.25, 1e-3}, true, stateAt(0.0));
  FakeSolve solve;
  ASSERT_TRUE(stepper.attemptStep(solve, 0.0, {}));
  stepper.commit({});
  solve.fails = [](const StepTrial &, double) { return true; };
  solve.unstable = true;
  int retries = 0;
  EXPECT_FALSE(stepper.attemptStep(solve, 0.0, [&retries](const StepTrial &) { ++retries; }));
  EXPECT_EQ(retries, 0);
}

TEST(LoadStepper, ACheckpointRestoredContinuesTheSameSteps) {
  LoadStepper original({1.0, 0.25, 1e-3}, true, stateAt(0.0));
  FakeSolve solve;
  for (int k = 0; k < 2; ++k) {
    ASSERT_TRUE(original.attemptStep(solve, 0.0, {}));
    original.commit({});
  }
  nlohmann::json part, run;
  original.save(part, run);
  LoadStepper restored({1.0, 0.25, 1e-3}, true, stateAt(0.0));
  restored.restore(part, run);
  EXPECT_EQ(restored.stepNumber(), 2);
  EXPECT_DOUBLE_EQ(restored.time(), 0.5);
  EXPECT_LT(distance(restored.committed(), 0.5), 1e-14);
  // The next start is the extrapolated one in both.
  FakeSolve a, b;
  ASSERT_TRUE(original.attemptStep(a, 0.0, {}));
  ASSERT_TRUE(restored.attemptStep(b, 0.0, {}));
  EXPECT_LT(b.startDistances[0], 1e-13);
  EXPECT_DOUBLE_EQ(a.startDistances[0], b.startDistances[0]);
}

TEST(LoadStepper, ACheckpointOfAnotherSizeIsRefused) {
  LoadStepper original({1.0, 0.25, 1e-3}, false, stateAt(0.0));
  nlohmann::json part, run;
  original.save(part, run);
  part["lambda"] = std::vector<double>(kElements + 1, 0.0);
  LoadStepper other({1.0, 0.25, 1e-3}, false, stateAt(0.0));
  EXPECT_ANY_THROW(other.restore(part, run));
}

namespace {
bool onLastRank() {
  const auto comm = Tpetra::getDefaultComm();
  return comm->getRank() == comm->getSize() - 1;
}
// The same on every rank (gathered to all).
bool sameOnEveryRank(int mine) {
  int low = 0, high = 0;
  Teuchos::reduceAll(*Tpetra::getDefaultComm(), Teuchos::REDUCE_MIN, mine, Teuchos::outArg(low));
  Teuchos::reduceAll(*Tpetra::getDefaultComm(), Teuchos::REDUCE_MAX, mine, Teuchos::outArg(high));
  return low == high;
}
} // namespace

// A solve that fails on the last rank alone (as a smoother on the coarse levels MueLu gathers onto
// one rank did): without agreement the other ranks committed the step while it cut back, and the
// job died in MPI_ERR_TRUNCATE at the next collective call.
TEST(LoadStepper, AStepThatFailsOnOneRankFailsOnEveryRank) {
  LoadStepper stepper({1.0, 0.25, 1e-3}, false, stateAt(0.0));
  FakeSolve solve;
  solve.fails = [](const StepTrial &trial, double) { return trial.dt > 0.1 && onLastRank(); };
  EXPECT_FALSE(stepper.attemptStep(solve, 0.0, {}));
  EXPECT_FALSE(stepper.trial().attempt.ok);
  const int ranks = Tpetra::getDefaultComm()->getSize();
  // The reason is the failing rank's, and says which rank it was on whichever rank reads it.
  const std::string where = "on rank " + std::to_string(ranks - 1) + " of " + std::to_string(ranks);
  if (onLastRank()) EXPECT_EQ(stepper.trial().attempt.why, "fake failure");
  else EXPECT_EQ(stepper.trial().attempt.why, "fake failure (" + where + ")");
  EXPECT_EQ(stepper.stepNumber(), 0);
  EXPECT_TRUE(stepper.cutBack());
  runToEnd(stepper, solve); // the step grows back and is cut back again, on every rank alike
  EXPECT_TRUE(sameOnEveryRank(stepper.stepNumber()));
  EXPECT_DOUBLE_EQ(stepper.time(), 1.0);
  EXPECT_TRUE(sameOnEveryRank(solve.attempts));
}

TEST(LoadStepper, AStepPastALimitPointOnOneRankIsSoOnEveryRank) {
  LoadStepper stepper({1.0, 0.25, 1e-3}, true, stateAt(0.0));
  FakeSolve solve;
  EXPECT_TRUE(stepper.attemptStep(solve, 0.0, {}));
  stepper.commit({});
  solve.fails = [](const StepTrial &, double) { return onLastRank(); };
  solve.unstable = onLastRank();
  int retries = 0;
  EXPECT_FALSE(stepper.attemptStep(solve, 0.0, [&retries](const StepTrial &) { ++retries; }));
  EXPECT_TRUE(stepper.trial().attempt.unstable);
  EXPECT_EQ(retries, 0); // not retried from the committed state, on any rank
  EXPECT_EQ(solve.attempts, 2);
}
