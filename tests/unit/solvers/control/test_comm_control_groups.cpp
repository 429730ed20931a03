// Control groups sharing a generation's candidates as they finish (solvers/control/
// CommControlGroups, claim): on 2 ranks, two groups of one rank each; on 1 rank, one group.
// Every candidate of every batch (empty ones included) is claimed by exactly one group, and a
// group that is busy gets none: group 1 makes its first claim of a batch only once group 0 has
// claimed the whole batch, so group 0 must have solved all of it, where dealing the candidates
// out in turn would have left it half. The batch's last claim (-1) is where all groups meet.
#include <gtest/gtest.h>

#include <mpi.h>

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_DefaultMpiComm.hpp>

#include "solvers/control/CommControlGroups.hpp"

using glossa::solvers::CommControlGroups;

namespace {
MPI_Comm rawWorld(const Teuchos::Comm<int> &comm) {
  return *dynamic_cast<const Teuchos::MpiComm<int> &>(comm).getRawMpiComm();
}
} // namespace

TEST(CommControlGroups, EveryCandidateOfEveryBatchIsSolvedOnce) {
  const auto world = Teuchos::DefaultComm<int>::getComm();
  const CommControlGroups groups(world, world->getSize());
  for (std::size_t size : {5u, 0u, 7u, 1u, 14u}) {
    std::vector<double> solved(size, 0.0);
    for (long i = groups.claim(size); i >= 0; i = groups.claim(size)) {
      ASSERT_LT(i, static_cast<long>(size));
      solved[static_cast<std::size_t>(i)] += 1.0;
    }
    const auto all = groups.sumOfGroupRoots(solved);
    for (double times : all) EXPECT_EQ(times, 1.0);
  }
}

TEST(CommControlGroups, ABusyGroupLeavesTheBatchToTheOther) {
  const auto world = Teuchos::DefaultComm<int>::getComm();
  if (world->getSize() != 2) GTEST_SKIP() << "two groups need two ranks";
  const CommControlGroups groups(world, 2);
  const MPI_Comm raw = rawWorld(*world);
  for (std::size_t size : {7u, 3u}) {
    if (groups.mine() == 0) {
      // Group 1 is busy: group 0 takes the whole batch, in order, then learns it is over.
      for (long k = 0; k < static_cast<long>(size); ++k) EXPECT_EQ(groups.claim(size), k);
      MPI_Send(nullptr, 0, MPI_INT, 1, 7, raw);
    } else {
      MPI_Recv(nullptr, 0, MPI_INT, 0, 7, raw, MPI_STATUS_IGNORE);
    }
    EXPECT_EQ(groups.claim(size), -1);
  }
}
