#pragma once
// Decisions every rank must take alike. A step that one rank cuts back while another commits it
// leaves the ranks in different collective calls (MPI_ERR_TRUNCATE, or a hang): whatever ends,
// retries or cuts back a step is reduced over the ranks first. Three reductions serve:
// - a failure on some ranks, its reason made known to all (the lowest failing rank's);
// - the largest of a measure that may be NaN on some ranks: NaN on every rank then. MPI_MAX with
//   a NaN is decided by the order in which a rank combines the values (a > b ? a : b keeps b when
//   either is NaN), so ranks could receive a NaN on one and a number on another;
// - whether any rank says yes.
// Teuchos only (no Tpetra), so any part of the solver side may use it.

#include <optional>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>

namespace glossa::assembly {

// True on every rank when `mine` is true on at least one. Collective.
bool anyRank(const Teuchos::Comm<int> &comm, bool mine);

// The largest of the ranks' values, entry by entry; an entry that is NaN on any rank is NaN on
// every rank. Collective; every rank passes as many values.
std::vector<double> largestOnAnyRank(const Teuchos::Comm<int> &comm, const std::vector<double> &mine);
double largestOnAnyRank(const Teuchos::Comm<int> &comm, double mine);

// A failure seen by some ranks, as every rank knows it: the lowest failing rank and its reason.
struct RankFailure {
  int rank = 0, ranks = 1;
  std::string reason;
  // "on rank R of N".
  std::string where() const;
};
// `mine`: this rank's reason, empty if it did not fail. Empty on every rank when no rank failed.
// Collective.
std::optional<RankFailure> failureOnAnyRank(const Teuchos::Comm<int> &comm, const std::optional<std::string> &mine);

} // namespace glossa::assembly
