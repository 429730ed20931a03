// The step-size rule as doc/theory.md states it: halve on failure down to the minimum, double
// after two successes in a row up to the nominal step, land on the end time.
#include <gtest/gtest.h>

#include "solvers/stepping/StepSizeController.hpp"

using glossa::solvers::StepSizeController;
using glossa::solvers::StepSizeRule;

TEST(StepSizeController, ACutBackIsRecoveredOnEasyStepsUpToTheNominalStep) {
  StepSizeController c(StepSizeRule{10.0, 0.8, 1e-3});
  EXPECT_DOUBLE_EQ(c.nextStep(0.0), 0.8);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(c.cutBack());
  EXPECT_DOUBLE_EQ(c.stepSize(), 0.1);
  // 2 log2(0.8 / 0.1) = 6 successes bring it back, and no further.
  const double expected[] = {0.1, 0.2, 0.2, 0.4, 0.4, 0.8, 0.8, 0.8};
  for (double dt : expected) {
    c.accept();
    EXPECT_DOUBLE_EQ(c.stepSize(), dt);
  }
}

TEST(StepSizeController, AFailureRestartsTheCountOfSuccesses) {
  StepSizeController c(StepSizeRule{10.0, 1.0, 1e-3});
  ASSERT_TRUE(c.cutBack()); // 0.5
  c.accept();
  ASSERT_TRUE(c.cutBack()); // 0.25: the success before it does not count
  c.accept();
  EXPECT_DOUBLE_EQ(c.stepSize(), 0.25);
  c.accept();
  EXPECT_DOUBLE_EQ(c.stepSize(), 0.5);
}

TEST(StepSizeController, StopsBelowTheMinimumAndLandsOnTheEndTime) {
  StepSizeController c(StepSizeRule{1.0, 0.3, 0.1});
  EXPECT_DOUBLE_EQ(c.nextStep(0.0), 0.3);
  EXPECT_NEAR(c.nextStep(0.6), 0.3, 1e-15);      // 0.4 left: a full step first
  EXPECT_NEAR(c.nextStep(0.9), 0.1, 1e-15);      // then the remainder, never past the end
  EXPECT_EQ(c.nextStep(0.70001), 1.0 - 0.70001); // within 0.01 % of a step: one step to the end, no sliver
  EXPECT_TRUE(c.cutBack());  // 0.15
  EXPECT_FALSE(c.cutBack()); // 0.075 < 0.1
  // A nominal step beyond the end time is the end time.
  EXPECT_DOUBLE_EQ(StepSizeController(StepSizeRule{2.0, 100.0, 1e-6}).nextStep(0.0), 2.0);
}
