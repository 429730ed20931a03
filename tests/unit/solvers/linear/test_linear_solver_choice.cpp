// Which linear solve a run gets (solvers/linear/LinearSolverChoice): the deck's explicit choices
// kept whatever the problem, and the rule of type = auto at its measured crossovers.
#include <gtest/gtest.h>

#include "solvers/linear/LinearSolverChoice.hpp"

namespace glossa::solvers {
namespace {

LinearSolverParameters section(LinearSolverType type) {
  LinearSolverParameters s;
  s.type = type;
  return s;
}

TEST(LinearSolverChoice, ExplicitTypesAreKeptWhateverTheProblem) {
  for (const long long n : {486LL, 20097LL, 151167LL})
    for (const int ranks : {1, 2, 4}) {
      EXPECT_TRUE(chooseLinearSolve(section(LinearSolverType::direct), {n, ranks, true}).direct);
      EXPECT_FALSE(chooseLinearSolve(section(LinearSolverType::iterative), {n, ranks, true}).direct);
    }
}

TEST(LinearSolverChoice, AutoSolvesSmallProblemsDirectlyOnOneAndTwoRanks) {
  const auto s = section(LinearSolverType::automatic);
  // Cook's membrane (486 unknowns), the §7.1 blocks (2,187), the coarse tongue (2,838).
  for (const long long n : {486LL, 2187LL, 2838LL})
    for (const int ranks : {1, 2}) {
      EXPECT_TRUE(chooseLinearSolve(s, {n, ranks, true}).direct) << n << " unknowns on " << ranks;
      EXPECT_TRUE(chooseLinearSolve(s, {n, ranks, false}).direct) << n << " unknowns on " << ranks;
    }
}

TEST(LinearSolverChoice, AutoSolvesLargeProblemsIteratively) {
  const auto s = section(LinearSolverType::automatic);
  // The medium tongue (20,097) and the fine one (151,167).
  for (const long long n : {20097LL, 151167LL})
    for (const int ranks : {1, 2}) EXPECT_FALSE(chooseLinearSolve(s, {n, ranks, false}).direct);
  EXPECT_FALSE(chooseLinearSolve(s, {0, 1, true}).direct); // nothing to factor
}

TEST(LinearSolverChoice, TheLimitIsDirectUpToOnOneRank) {
  auto s = section(LinearSolverType::automatic);
  s.directUpTo = 1000;
  EXPECT_EQ(autoDirectLimit(s, {1000, 1, true}), 1000);
  EXPECT_TRUE(chooseLinearSolve(s, {1000, 1, true}).direct);
  EXPECT_FALSE(chooseLinearSolve(s, {1001, 1, true}).direct);
  s.directUpTo = 0; // never direct
  EXPECT_FALSE(chooseLinearSolve(s, {10, 1, true}).direct);
  EXPECT_FALSE(chooseLinearSolve(s, {10, 2, true}).direct);
}

TEST(LinearSolverChoice, AutoGathersItsDirectSolveOnSeveralRanks) {
  const auto s = section(LinearSolverType::automatic);
  EXPECT_FALSE(chooseLinearSolve(s, {486, 1, true}).gathered); // one rank: nothing to gather
  EXPECT_TRUE(chooseLinearSolve(s, {486, 2, true}).gathered);
  EXPECT_TRUE(chooseLinearSolve(s, {486, 4, false}).gathered);
}

TEST(LinearSolverChoice, TypeDirectIsDistributedUnlessTheDeckGathersIt) {
  auto s = section(LinearSolverType::direct);
  EXPECT_FALSE(chooseLinearSolve(s, {486, 2, true}).gathered);
  s.directDistribution = DirectDistribution::gathered;
  EXPECT_TRUE(chooseLinearSolve(s, {486, 2, true}).gathered);
  auto a = section(LinearSolverType::automatic);
  a.directDistribution = DirectDistribution::distributed;
  EXPECT_FALSE(chooseLinearSolve(a, {486, 2, true}).gathered);
}

} // namespace
} // namespace glossa::solvers
