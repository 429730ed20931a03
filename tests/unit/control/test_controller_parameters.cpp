// Validation of GeneticAlgorithmParameters and ControllerParameters: defaults are valid; each
// bad field is an std::invalid_argument naming the field and its allowed range.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "control/ControllerParameters.hpp"
#include "control/ElitistGeneticAlgorithm.hpp"

namespace glossa::control {
namespace {

// The message of the std::invalid_argument that validate() throws after `edit`.
std::string errorAfter(const std::function<void(ControllerParameters &)> &edit) {
  ControllerParameters c;
  edit(c);
  try {
    c.validate();
  } catch (const std::invalid_argument &e) {
    return e.what();
  }
  return "";
}

void expectError(const std::function<void(ControllerParameters &)> &edit, const std::string &field,
                 const std::string &range) {
  const std::string message = errorAfter(edit);
  EXPECT_NE(message.find(field), std::string::npos) << "'" << message << "' does not name " << field;
  EXPECT_NE(message.find(range), std::string::npos) << "'" << message << "' does not give " << range;
}

TEST(ControllerParameters, DefaultsAreValid) {
  EXPECT_NO_THROW(ControllerParameters().validate());
  EXPECT_NO_THROW(GeneticAlgorithmParameters().validate());
}

TEST(ControllerParameters, EachBadFieldIsNamedWithItsRange) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expectError([](auto &c) { c.ga.populationSize = 1; }, "ga.populationSize = 1", "[2, inf)");
  expectError([](auto &c) { c.ga.generations = 0; }, "ga.generations = 0", "[1, inf)");
  expectError([](auto &c) { c.ga.eliteCount = 0; }, "ga.eliteCount = 0", "[1, 15]");
  expectError([](auto &c) { c.ga.eliteCount = 16; }, "ga.eliteCount = 16", "[1, 15]");
  expectError([](auto &c) { c.ga.tournamentSize = 17; }, "ga.tournamentSize = 17", "[1, 16]");
  expectError([](auto &c) { c.ga.crossoverRate = 1.5; }, "ga.crossoverRate = 1.5", "[0, 1]");
  expectError([](auto &c) { c.ga.mutationRate = -0.1; }, "ga.mutationRate = -0.1", "[0, 1]");
  expectError([](auto &c) { c.ga.mutationSigma = 0.0; }, "ga.mutationSigma = 0", "(0, inf)");
  expectError([](auto &c) { c.ga.geneResolution = 0.6; }, "ga.geneResolution = 0.6", "[0, 0.5]");
  expectError([](auto &c) { c.ga.stagnationGenerations = -1; }, "ga.stagnationGenerations = -1", "[0, inf)");
  expectError([nan](auto &c) { c.ga.minImprovement = nan; }, "ga.minImprovement", "[0, inf)");
  expectError([](auto &c) { c.ga.objectiveTolerance = -1e-3; }, "ga.objectiveTolerance", "[0, inf)");
  expectError([](auto &c) { c.pruningTolerance = -0.01; }, "pruningTolerance = -0.01", "[0, inf)");
  expectError([](auto &c) { c.effortWeight = -1e-4; }, "effortWeight = -0.0001", "[0, inf)");
  expectError([](auto &c) { c.sensitivityPenaltyRatio = 0.5; }, "sensitivityPenaltyRatio = 0.5", "[1, 1e+08]");
  expectError([nan](auto &c) { c.sensitivityPenaltyRatio = nan; }, "sensitivityPenaltyRatio", "[1, 1e+08]");
  expectError([](auto &c) { c.alwaysEvaluated = {"GGa", ""}; }, "alwaysEvaluated[1]", "group name");
  expectError([](auto &c) { c.alwaysEvaluated = {"GGa", "GGa"}; }, "alwaysEvaluated[1]", "twice");
  // The GA's constructor validates too (without the "ga." prefix).
  GeneticAlgorithmParameters p;
  p.populationSize = 0;
  EXPECT_THROW(ElitistGeneticAlgorithm{p}, std::invalid_argument);
}

TEST(ControllerParameters, AlwaysEvaluatedMask) {
  ControllerParameters c;
  c.alwaysEvaluated = {"GGp", "GGa"};
  EXPECT_EQ(c.alwaysEvaluatedMask({"GGa", "SL", "GGp", "TV"}), (std::vector<bool>{true, false, true, false}));
  c.alwaysEvaluated = {"GGx"};
  EXPECT_THROW(c.alwaysEvaluatedMask({"GGa"}), std::invalid_argument);
}

}  // namespace
}  // namespace glossa::control
