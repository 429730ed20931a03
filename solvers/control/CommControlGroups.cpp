#include "solvers/control/CommControlGroups.hpp"

#include <Teuchos_CommHelpers.hpp>

namespace glossa::solvers {

CommControlGroups::CommControlGroups(Teuchos::RCP<const Teuchos::Comm<int>> world, int count)
    : world_(std::move(world)), count_(count), size_(world_->getSize() / count), mine_(world_->getRank() / size_) {
  group_ = count_ == 1 ? world_ : Teuchos::RCP<const Teuchos::Comm<int>>(world_->split(mine_, world_->getRank()));
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
