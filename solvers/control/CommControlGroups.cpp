#include "solvers/control/CommControlGroups.hpp"

#include <exception>
#include <stdexcept>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>

namespace glossa::solvers {

CommControlGroups::CommControlGroups(Teuchos::RCP<const Teuchos::Comm<int>> world, int count)
    : world_(std::move(world)), count_(count), size_(world_->getSize() / count), mine_(world_->getRank() / size_) {
  group_ = count_ == 1 ? world_ : Teuchos::RCP<const Teuchos::Comm<int>>(world_->split(mine_, world_->getRank()));
  if (count_ == 1) return;
  const auto *mpi = dynamic_cast<const Teuchos::MpiComm<int> *>(world_.get());
  if (!mpi) throw std::logic_error("control groups need an MPI communicator");
  const MPI_Comm raw = *mpi->getRawMpiComm();
  long *counter = nullptr;
  const MPI_Aint bytes = world_->getRank() == 0 ? static_cast<MPI_Aint>(sizeof(long)) : 0;
  MPI_Win_allocate(bytes, sizeof(long), MPI_INFO_NULL, raw, &counter, &counter_);
  if (world_->getRank() == 0) {
    MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, counter_);
    *counter = 0;
    MPI_Win_unlock(0, counter_);
  }
  MPI_Barrier(raw); // no claim before the counter is 0
}

CommControlGroups::~CommControlGroups() {
  // Freeing the window is collective: while an exception unwinds on one rank the others are
  // elsewhere, and the job is ending anyway.
  if (counter_ != MPI_WIN_NULL && std::uncaught_exceptions() == 0) MPI_Win_free(&counter_);
}

long CommControlGroups::claim(std::size_t size) const {
  // The counter holds how many claims all batches so far have seen: a batch's candidates, then
  // one claim past its end for each group. The groups meet once every group has made that last
  // claim, so the next batch's claims start after all of them. (A fetch-and-add, not a compare
  // and swap that would take no number past the end: Open MPI 4.1's one-sided component over
  // shared memory crashes in its emulated compare and swap.)
  long taken = 0;
  if (counter_ == MPI_WIN_NULL) { // one group: nothing to share
    taken = claimed_++;
  } else {
    if (group_->getRank() == 0) {
      const long one = 1;
      MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, counter_);
      MPI_Fetch_and_op(&one, &taken, MPI_LONG, 0, 0, MPI_SUM, counter_);
      MPI_Win_unlock(0, counter_);
    }
    Teuchos::broadcast(*group_, 0, Teuchos::outArg(taken));
  }
  const long index = taken - batchStart_;
  if (index < static_cast<long>(size)) return index;
  batchStart_ += static_cast<long>(size) + count_;
  if (counter_ != MPI_WIN_NULL) world_->barrier();
  return -1;
}

std::vector<double> CommControlGroups::sumOfGroupRoots(const std::vector<double> &values) const {
  // Exact whatever the order of the sum: each entry has at most one non-zero term.
  std::vector<double> mineOnly = values, all(values.size(), 0.0);
  if (group_->getRank() != 0) std::fill(mineOnly.begin(), mineOnly.end(), 0.0);
  Teuchos::reduceAll(*world_, Teuchos::REDUCE_SUM, static_cast<int>(mineOnly.size()), mineOnly.data(), all.data());
  return all;
}

void CommControlGroups::broadcastFromGroup(int from, std::vector<double> &buffer) const {
  const int root = from * size_;
  int size = static_cast<int>(buffer.size());
  Teuchos::broadcast(*world_, root, Teuchos::outArg(size));
  buffer.resize(static_cast<std::size_t>(size));
  Teuchos::broadcast(*world_, root, size, buffer.data());
}

} // namespace glossa::solvers
