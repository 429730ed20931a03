// The limit-point monitor's bookkeeping on a made-up load path: the first finite positive
// stiffness is the reference, a negative one is past the limit point, and the bracket closes on
// the limit point as the step is cut back, then names it.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "solvers/stepping/LimitPointMonitor.hpp"

using glossa::solvers::LimitPointMonitor;

TEST(LimitPointMonitor, StiffnessIsRelativeToTheFirstMeasuredStep) {
  LimitPointMonitor m(0.1, 0.01);
  EXPECT_TRUE(std::isnan(m.relativeStiffness(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_TRUE(std::isnan(m.relativeStiffness(-3.0))); // no reference yet: nothing to compare with
  EXPECT_DOUBLE_EQ(m.relativeStiffness(4.0), 1.0);
  EXPECT_DOUBLE_EQ(m.relativeStiffness(1.0), 0.25);
  EXPECT_DOUBLE_EQ(m.relativeStiffness(-2.0), -0.5);
  EXPECT_TRUE(LimitPointMonitor::beyond(-0.5));
  EXPECT_TRUE(LimitPointMonitor::beyond(0.0));
  EXPECT_FALSE(LimitPointMonitor::beyond(1e-9));
  EXPECT_FALSE(LimitPointMonitor::beyond(std::numeric_limits<double>::quiet_NaN()));
}

// Load control on p(t) with a maximum at t* = 0.9071 (the thick sphere's 0.8164 of 0.9): the
// stiffness along the path S(t) = sqrt((t* - t) / t*) before it; past it no state converges.
TEST(LimitPointMonitor, BracketsAndLocatesTheMaximum) {
  const double tStar = 0.9071, nominal = 0.1;
  LimitPointMonitor m(nominal, 0.01);
  double t = 0.0, dt = nominal;
  bool located = false;
  int attempts = 0;
  while (!located && ++attempts < 200) {
    const double trial = t + dt;
    if (trial < tStar) {
      m.accepted(trial, std::sqrt((tStar - trial) / tStar));
      t = trial; // (the step does not grow back here: the bisection alone)
    } else {
      m.refused(t, trial, false, 7);
      dt *= 0.5;
      located = m.located(dt);
    }
  }
  ASSERT_TRUE(located);
  const auto r = m.record(Eigen::Vector3d(1, 2, 3));
  const double lower = r["bracket"][0], upper = r["bracket"][1];
  EXPECT_LE(lower, tStar);
  EXPECT_GE(upper, tStar);
  EXPECT_LT(upper - lower, 2 * 0.01 * nominal);
  EXPECT_EQ(r["node"], 7);
  EXPECT_FALSE(r["unstable_states_found"]);
  EXPECT_NE(m.description(Eigen::Vector3d(1, 2, 3)).find("limit point of the load path between t = "), std::string::npos);
}

// A failure on a path that has not softened is no limit point (Newton's own trouble); an
// unstable converged state is one, wherever the path's stiffness stood.
TEST(LimitPointMonitor, OnlySofteningOrInstabilityOpensABracket) {
  LimitPointMonitor stiff(0.1, 0.01);
  stiff.accepted(0.1, 0.9);
  stiff.refused(0.1, 0.2, false, 0);
  EXPECT_FALSE(stiff.located(0.0));

  LimitPointMonitor jumped(0.1, 0.01);
  jumped.accepted(0.1, 0.9);
  jumped.refused(0.1, 0.2, true, 3);
  EXPECT_FALSE(jumped.located(0.05)); // the step is still large
  EXPECT_TRUE(jumped.located(0.0005));
  EXPECT_TRUE(jumped.record(Eigen::Vector3d::Zero())["unstable_states_found"]);

  // A step past the bracket that converges after all: not a maximum of this path.
  jumped.accepted(0.25, 0.8);
  EXPECT_FALSE(jumped.located(0.0));
}
