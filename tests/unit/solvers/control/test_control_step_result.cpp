// A control step's result survives the flat buffer it is broadcast in bit for bit, awkward
// values included (-0, a subnormal, infinity, characters beyond ASCII), at any offset; a
// truncated buffer is refused.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>

#include "solvers/control/ControlStepResult.hpp"

using glossa::solvers::ControlStepResult;
using glossa::solvers::NewtonResult;

namespace {
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameBits(const std::vector<double> &a, const std::vector<double> &b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

ControlStepResult awkwardResult() {
  ControlStepResult r;
  r.inputs = {0.1, -0.0, 1.0 / 3.0, std::numeric_limits<double>::denorm_min(), 1.0};
  r.evaluated = {0, 2, 4};
  r.objective = 1.0 / 7.0;
  r.candidates = 123456789;
  r.generations = 17;
  r.iterations = 3;
  r.sensitivities = 2;
  r.sensitivityKrylov = 41;
  r.sensitivityCheck = -1.0;
  r.failedCandidates = 3;
  r.screenedCandidates = 2;
  r.solvedAgainCandidates = 5;
  r.couplingIterations = 7;
  r.couplingChange = 0.0371;
  r.firstFailure = "CG met negative curvature";
  r.stop = "objective tolerance \xc3\xbc"; // a UTF-8 u-umlaut: two bytes above 127
  r.pointErrors = Eigen::Vector3d(2.5e-8, std::numeric_limits<double>::infinity(), 0.0);
  r.solve.converged = true;
  r.solve.elementInverted = false;
  r.solve.solves = 2;
  r.solve.newtonIterations = 9;
  r.solve.linearIterations = 120;
  r.solve.dilatation = {3e-9, 1e-10, 0.02};
  NewtonResult a;
  a.converged = false;
  a.elementInverted = true;
  a.iterations = 5;
  a.linearIterations = 70;
  a.residualNorms = {1.0, 0.1, 1e-3, 1e-7, 1e-13};
  a.linearIterationsPerStep = {10, 12, 15, 16, 17};
  a.failure = "line search failed\nsecond line";
  NewtonResult b;
  b.converged = true;
  b.iterations = 4;
  b.residualNorms = {1e-3, 1e-14};
  r.solve.newton = {a, b};
  return r;
}
} // namespace

TEST(ControlStepResult, RoundTripIsBitForBit) {
  const ControlStepResult r = awkwardResult();
  std::vector<double> buffer{42.0, -1.0}; // what precedes it
  glossa::solvers::appendControlStepResult(r, buffer);
  const std::size_t end = buffer.size();
  buffer.push_back(7.0); // what follows it (a plant's state)
  std::size_t position = 2;
  const ControlStepResult back = glossa::solvers::readControlStepResult(buffer, position);
  EXPECT_EQ(position, end);

  EXPECT_TRUE(sameBits(back.inputs, r.inputs));
  EXPECT_TRUE(std::signbit(back.inputs[1]));
  EXPECT_EQ(back.evaluated, r.evaluated);
  EXPECT_TRUE(sameBits(back.objective, r.objective));
  EXPECT_EQ(back.candidates, r.candidates);
  EXPECT_EQ(back.generations, r.generations);
  EXPECT_EQ(back.iterations, r.iterations);
  EXPECT_EQ(back.sensitivities, r.sensitivities);
  EXPECT_EQ(back.sensitivityKrylov, r.sensitivityKrylov);
  EXPECT_TRUE(sameBits(back.sensitivityCheck, r.sensitivityCheck));
  EXPECT_EQ(back.failedCandidates, r.failedCandidates);
  EXPECT_EQ(back.screenedCandidates, r.screenedCandidates);
  EXPECT_EQ(back.solvedAgainCandidates, r.solvedAgainCandidates);
  EXPECT_EQ(back.couplingIterations, r.couplingIterations);
  EXPECT_TRUE(sameBits(back.couplingChange, r.couplingChange));
  EXPECT_EQ(back.firstFailure, r.firstFailure);
  EXPECT_EQ(back.stop, r.stop);
  ASSERT_EQ(back.pointErrors.size(), r.pointErrors.size());
  for (Eigen::Index p = 0; p < r.pointErrors.size(); ++p) EXPECT_TRUE(sameBits(back.pointErrors(p), r.pointErrors(p)));

  const auto &s = back.solve;
  EXPECT_EQ(s.converged, r.solve.converged);
  EXPECT_EQ(s.elementInverted, r.solve.elementInverted);
  EXPECT_EQ(s.solves, r.solve.solves);
  EXPECT_EQ(s.newtonIterations, r.solve.newtonIterations);
  EXPECT_EQ(s.linearIterations, r.solve.linearIterations);
  EXPECT_TRUE(sameBits(s.dilatation.max, r.solve.dilatation.max));
  EXPECT_TRUE(sameBits(s.dilatation.mean, r.solve.dilatation.mean));
  EXPECT_TRUE(sameBits(s.dilatation.maxVolumeChange, r.solve.dilatation.maxVolumeChange));
  ASSERT_EQ(s.newton.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const NewtonResult &n = s.newton[i], &m = r.solve.newton[i];
    EXPECT_EQ(n.converged, m.converged) << i;
    EXPECT_EQ(n.elementInverted, m.elementInverted) << i;
    EXPECT_EQ(n.iterations, m.iterations) << i;
    EXPECT_EQ(n.linearIterations, m.linearIterations) << i;
    EXPECT_TRUE(sameBits(n.residualNorms, m.residualNorms)) << i;
    EXPECT_EQ(n.linearIterationsPerStep, m.linearIterationsPerStep) << i;
    EXPECT_EQ(n.failure, m.failure) << i;
  }

  // Written again, the copy gives the same buffer.
  std::vector<double> again{42.0, -1.0};
  glossa::solvers::appendControlStepResult(back, again);
  again.push_back(7.0);
  EXPECT_TRUE(sameBits(again, buffer));
}

TEST(ControlStepResult, FoundOnlyWithAFiniteObjective) {
  ControlStepResult r;
  r.objective = 0.0;
  EXPECT_TRUE(r.found());
  r.objective = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(r.found());
}

TEST(ControlStepResult, TruncatedBufferIsRefused) {
  std::vector<double> buffer;
  glossa::solvers::appendControlStepResult(awkwardResult(), buffer);
  buffer.pop_back();
  std::size_t position = 0;
  EXPECT_THROW(glossa::solvers::readControlStepResult(buffer, position), std::runtime_error);
}
