#pragma once
// What MUMPS reported of the run's last numeric factorisation, for summary.json: the ordering it
// used, the entries of the factors and the flops of the elimination (its INFOG(7), INFOG(29) and
// RINFOG(3), totals over the ranks that factor). They depend only on the pattern, the ordering
// and the pivots, not on the machine, so they compare orderings free of timing noise
// (bench/direct_ordering.py). A light header: the run's report reads it without MUMPS or Thyra.

#include <string>

namespace glossa::solvers {

struct DirectFactorStatistics {
  std::string ordering;       // "PORD", "AMF", ...; empty: no direct factorisation in this run
  double factorEntries = 0.0; // entries of L and U (of L alone for LDL^T)
  double flops = 0.0;         // floating-point operations of one elimination
};

// The last factorisation's on this process (every rank of a shared factorisation agrees).
const DirectFactorStatistics &lastDirectFactorisation();

} // namespace glossa::solvers
