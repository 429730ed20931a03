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
      EXPECT_TRUE(chooseLinearSolve(section(LinearSolverType::direct), {n, ranks}).direct);
      EXPECT_FALSE(chooseLinearSolve(section(LinearSolverType::iterative), {n, ranks}).direct);
    }
}

TEST(LinearSolverChoice, AutoSolvesSmallProblemsDirectlyOnOneAndTwoRanks) {
  const auto s = section(LinearSolverType::automatic);
  // Cook's membrane (486 unknowns), the §7.1 blocks (2,187), the coarse tongue (2,838).
  for (const long long n : {486LL, 2187LL, 2838LL})
    for (const int ranks : {1, 2}) {
      EXPECT_TRUE(chooseLinearSolve(s, {n, ranks}).direct) << n << " unknowns on " << ranks;
    }
}

TEST(LinearSolverChoice, AutoSolvesLargeProblemsIteratively) {
  const auto s = section(LinearSolverType::automatic);
  // The medium tongue (20,097) and the fine one (151,167).
  for (const long long n : {20097LL, 151167LL})
    for (const int ranks : {1, 2}) EXPECT_FALSE(chooseLinearSolve(s, {n, ranks}).direct);
  EXPECT_FALSE(chooseLinearSolve(s, {0, 1}).direct); // nothing to factor
}

TEST(LinearSolverChoice, TheLimitIsDirectUpToOnOneRank) {
  auto s = section(LinearSolverType::automatic);
  s.directUpTo = 1000;
  EXPECT_EQ(autoDirectLimit(s, {1000, 1}), 1000);
  EXPECT_TRUE(chooseLinearSolve(s, {1000, 1}).direct);
  EXPECT_FALSE(chooseLinearSolve(s, {1001, 1}).direct);
  s.directUpTo = 0; // never direct
  EXPECT_FALSE(chooseLinearSolve(s, {10, 1}).direct);
  EXPECT_FALSE(chooseLinearSolve(s, {10, 2}).direct);
}

// The limit is 'direct up to' on any rank count (measured: on 2 ranks the direct solve still won
// at 6,591 unknowns); up to 'direct up to' / R the solve is gathered onto rank 0, above it
// distributed over the ranks (the gathered factorisation costs one rank's).
TEST(LinearSolverChoice, OnSeveralRanksLargerDirectSolvesAreDistributed) {
  const auto s = section(LinearSolverType::automatic);
  EXPECT_EQ(autoDirectLimit(s, {0, 1}), 8000);
  EXPECT_EQ(autoDirectLimit(s, {0, 2}), 8000);
  EXPECT_TRUE(chooseLinearSolve(s, {4000, 2}).gathered);
  EXPECT_TRUE(chooseLinearSolve(s, {6591, 2}).direct);
  EXPECT_FALSE(chooseLinearSolve(s, {6591, 2}).gathered);
  EXPECT_TRUE(chooseLinearSolve(s, {8000, 2}).direct);
  EXPECT_FALSE(chooseLinearSolve(s, {8001, 2}).direct);
  EXPECT_TRUE(chooseLinearSolve(s, {2000, 4}).gathered);
  EXPECT_FALSE(chooseLinearSolve(s, {2001, 4}).gathered);
}

TEST(LinearSolverChoice, AutoGathersItsDirectSolveOnSeveralRanks) {
  const auto s = section(LinearSolverType::automatic);
  EXPECT_FALSE(chooseLinearSolve(s, {486, 1}).gathered); // one rank: nothing to gather
  EXPECT_TRUE(chooseLinearSolve(s, {486, 2}).gathered);
  EXPECT_TRUE(chooseLinearSolve(s, {486, 4}).gathered);
}

TEST(LinearSolverChoice, TypeDirectIsDistributedUnlessTheDeckGathersIt) {
  auto s = section(LinearSolverType::direct);
  EXPECT_FALSE(chooseLinearSolve(s, {486, 2}).gathered);
  s.directDistribution = DirectDistribution::gathered;
  EXPECT_TRUE(chooseLinearSolve(s, {486, 2}).gathered);
  auto a = section(LinearSolverType::automatic);
  a.directDistribution = DirectDistribution::distributed;
  EXPECT_FALSE(chooseLinearSolve(a, {486, 2}).gathered);
}

// A controller's sensitivities beside iterative Newton solves: factored by MUMPS up to the
// medium tongue's size, where it was measured to halve their cost; the deck's choice either way.
TEST(LinearSolverChoice, SensitivitiesAreFactoredUpToTheMeasuredSize) {
  auto s = section(LinearSolverType::automatic);
  EXPECT_TRUE(directSensitivitySolve(s, {20097, 2}));
  EXPECT_TRUE(directSensitivitySolve(s, {kSensitivityDirectUpTo, 1}));
  EXPECT_FALSE(directSensitivitySolve(s, {kSensitivityDirectUpTo + 1, 2}));
  EXPECT_TRUE(directSensitivitySolve(s, {2838, 2})); // where Newton's solve is MUMPS
  s.directSolver = DirectSolver::klu2;
  EXPECT_FALSE(directSensitivitySolve(s, {2838, 1})); // KLU2 is kept for comparison
  EXPECT_TRUE(directSensitivitySolve(s, {20097, 1}));
  s.sensitivitySolve = SensitivitySolve::asNewton;
  EXPECT_FALSE(directSensitivitySolve(s, {20097, 2}));
  EXPECT_FALSE(directSensitivitySolve(s, {2838, 2}));
  s.sensitivitySolve = SensitivitySolve::direct;
  EXPECT_TRUE(directSensitivitySolve(s, {151167, 2}));
}

} // namespace
} // namespace glossa::solvers
