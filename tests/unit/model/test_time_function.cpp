// Time functions against their definitions, including the piecewise-constant steps used for
// neural inputs and the scaling that gives a constant input below 1.
#include <cmath>

#include <gtest/gtest.h>

#include "input/TimeFunctionParameters.hpp"
#include "model/TimeFunction.hpp"

using glossa::model::TimeFunction;

TEST(TimeFunction, StepsHoldEachValueUntilTheNextTime) {
  const auto f = TimeFunction::steps({0.1, 0.3}, {1.0, 0.25});
  EXPECT_EQ(f(0.0), 1.0); // values[0] before the first time
  EXPECT_EQ(f(0.1), 1.0);
  EXPECT_EQ(f(0.2999), 1.0);
  EXPECT_EQ(f(0.3), 0.25);
  EXPECT_EQ(f(7.0), 0.25);
  EXPECT_THROW(TimeFunction::steps({0.3, 0.1}, {1, 0}), std::invalid_argument);
}

TEST(TimeFunction, TableAndRampAndScaling) {
  const auto table = TimeFunction::table({0.0, 1.0}, {0.0, 2.0});
  EXPECT_DOUBLE_EQ(table(0.25), 0.5);
  EXPECT_DOUBLE_EQ(table.scaled(0.5)(0.25), 0.25);
  EXPECT_DOUBLE_EQ(TimeFunction::ramp(2.0)(1.0), 0.5);
  EXPECT_DOUBLE_EQ(TimeFunction::constant().scaled(0.3)(10.0), 0.3);
}

TEST(TimeFunction, FromParametersReadsSteps) {
  auto p = glossa::input::timeFunctionParameters("constant");
  EXPECT_EQ(p.get<std::string>("type"), "constant");
  p.set("type", std::string("steps"));
  p.set("times", Teuchos::Array<double>(std::vector<double>{0.0, 0.5}));
  p.set("values", Teuchos::Array<double>(std::vector<double>{1.0, 0.0}));
  const auto f = glossa::input::parseTimeFunction(p, 1.0);
  EXPECT_EQ(f(0.49), 1.0);
  EXPECT_EQ(f(0.5), 0.0);
}

TEST(TimeFunction, BreathingFromParametersIsEq27HalfWave) {
  auto p = glossa::input::timeFunctionParameters();
  p.set("type", std::string("breathing"));
  const auto f = glossa::input::parseTimeFunction(p, 1.0);
  const double omega = 2 * M_PI / 2.5;
  EXPECT_NEAR(f(0.3), std::pow(std::sin(omega * 0.3), 1.75), 1e-15);
  EXPECT_EQ(f(1.5), 0.0); // second half of the breath: no pressure
  p.set("rectification", std::string("full-wave"));
  EXPECT_NEAR(glossa::input::parseTimeFunction(p, 1.0)(1.5), std::pow(std::abs(std::sin(omega * 1.5)), 1.75), 1e-15);
}
