#include "assembly/RankAgreement.hpp"

#include <cmath>
#include <limits>

#include <Teuchos_CommHelpers.hpp>

namespace glossa::assembly {

bool anyRank(const Teuchos::Comm<int> &comm, bool mine) {
  int local = mine ? 1 : 0, any = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local, Teuchos::outArg(any));
  return any != 0;
}

std::vector<double> largestOnAnyRank(const Teuchos::Comm<int> &comm, const std::vector<double> &mine) {
  // Each value, NaN taken as +inf, then a 0/1 flag of its NaN: one reduction of twice the length.
  const std::size_t n = mine.size();
  std::vector<double> local(2 * n), global(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool nan = std::isnan(mine[i]);
    local[i] = nan ? std::numeric_limits<double>::infinity() : mine[i];
    local[n + i] = nan ? 1.0 : 0.0;
  }
  if (n > 0) Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, static_cast<int>(2 * n), local.data(), global.data());
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = global[n + i] > 0.0 ? std::numeric_limits<double>::quiet_NaN() : global[i];
  return out;
}

double largestOnAnyRank(const Teuchos::Comm<int> &comm, double mine) {
  return largestOnAnyRank(comm, std::vector<double>{mine})[0];
}

std::string RankFailure::where() const {
  return "on rank " + std::to_string(rank) + " of " + std::to_string(ranks);
}

std::optional<RankFailure> failureOnAnyRank(const Teuchos::Comm<int> &comm, const std::optional<std::string> &mine) {
  const int rank = comm.getRank(), size = comm.getSize();
  int first = size;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, mine ? rank : size, Teuchos::outArg(first));
  if (first == size) return std::nullopt;
  std::string reason = rank == first ? *mine : std::string();
  int length = static_cast<int>(reason.size());
  Teuchos::broadcast(comm, first, Teuchos::outArg(length));
  reason.resize(static_cast<std::size_t>(length));
  if (length > 0) Teuchos::broadcast(comm, first, length, reason.data());
  return RankFailure{first, size, reason};
}

} // namespace glossa::assembly
