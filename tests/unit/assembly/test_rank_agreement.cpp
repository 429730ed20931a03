// The ranks' agreement, on 1 rank and under mpiexec on 2, with the last rank the odd one out:
// - a failure on the last rank alone reaches every rank with its rank and reason, and with several
//   failures the lowest rank's reason wins;
// - a NaN on the last rank alone is NaN on every rank (MPI_MAX alone may drop it on some), and
//   without one the largest value is every rank's;
// - one rank's yes is every rank's.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Tpetra_Core.hpp>

#include "assembly/RankAgreement.hpp"

using namespace glossa::assembly;

namespace {
const Teuchos::Comm<int> &world() { return *Tpetra::getDefaultComm(); }
int rank() { return world().getRank(); }
int last() { return world().getSize() - 1; }
} // namespace

TEST(RankAgreement, AFailureOnTheLastRankAloneReachesEveryRank) {
  const std::optional<std::string> mine =
      rank() == last() ? std::optional<std::string>("the smoother's eigenvalue estimate is NaN") : std::nullopt;
  const auto failure = failureOnAnyRank(world(), mine);
  ASSERT_TRUE(failure.has_value());
  EXPECT_EQ(failure->rank, last());
  EXPECT_EQ(failure->ranks, world().getSize());
  EXPECT_EQ(failure->reason, "the smoother's eigenvalue estimate is NaN");
  EXPECT_EQ(failure->where(), "on rank " + std::to_string(last()) + " of " + std::to_string(world().getSize()));
}

TEST(RankAgreement, NoFailureIsNoFailureAnywhereAndTheLowestFailingRankSpeaks) {
  EXPECT_FALSE(failureOnAnyRank(world(), std::nullopt).has_value());
  const auto failure = failureOnAnyRank(world(), "reason of rank " + std::to_string(rank()));
  ASSERT_TRUE(failure.has_value());
  EXPECT_EQ(failure->rank, 0);
  EXPECT_EQ(failure->reason, "reason of rank 0");
  // An empty reason is a failure too.
  const auto silent = failureOnAnyRank(world(), rank() == last() ? std::optional<std::string>("") : std::nullopt);
  ASSERT_TRUE(silent.has_value());
  EXPECT_EQ(silent->reason, "");
}

TEST(RankAgreement, ANaNOnTheLastRankIsNaNOnEveryRank) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // The NaN last, after the larger value, and first, before it: both ways round.
  const std::vector<double> mine = rank() == last() ? std::vector<double>{nan, 2.0, nan} : std::vector<double>{7.0, 1.0, -3.0};
  const std::vector<double> largest = largestOnAnyRank(world(), mine);
  ASSERT_EQ(largest.size(), 3u);
  EXPECT_TRUE(std::isnan(largest[0]));
  EXPECT_EQ(largest[1], 2.0);
  EXPECT_TRUE(std::isnan(largest[2]));
  EXPECT_EQ(largestOnAnyRank(world(), static_cast<double>(rank()) - 0.5), static_cast<double>(last()) - 0.5);
  EXPECT_EQ(largestOnAnyRank(world(), std::numeric_limits<double>::infinity()), std::numeric_limits<double>::infinity());
  EXPECT_TRUE(largestOnAnyRank(world(), std::vector<double>{}).empty());
}

TEST(RankAgreement, OneRanksYesIsEveryRanks) {
  EXPECT_TRUE(anyRank(world(), rank() == last()));
  EXPECT_FALSE(anyRank(world(), false));
}
