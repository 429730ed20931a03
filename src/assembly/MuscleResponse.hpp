#pragma once
// The muscle state at a converged step, beside the assembly: the point laws and the external
// fibres evaluated at the converged displacement, their contractile stretches written to the
// history's trial values, and what the output and the controllers read from them, among which
// the pruning measure of §6.1 (each group's length-weighted mean fibre stretch).

#include <vector>

#include "assembly/ResultEvaluator.hpp"
#include "model/MuscleHistory.hpp"

namespace glossa::assembly {

// What the muscle point laws computed at the converged displacement of a step.
struct MuscleFields {
  bool valid = true; // false: a local contractile solve failed (on any rank)
  int groups = 0;
  // Per local element and group (index i * groups + g): the mean over the element's points and
  // the group's families of the fibre stretch and the contractile stretch; 0 where the group is
  // absent.
  std::vector<double> fibreStretch, contractileStretch;
  std::vector<double> fibreStress; // per local element: mean of sum_f phi_f T_f [Pa]
  // Per group, over the whole mesh: the length-weighted mean fibre stretch of its internal
  // families (the pruning measure of §6.1: each point weighted by the fibre length its element
  // holds along the family's reference direction, control::fibreLengthMeasure, times its share
  // of the element's volume); for a group with external fibres only, their reference-length-
  // weighted mean stretch; NaN for a group with no fibres. The same mean of the contractile
  // stretch lambda_c (of the external fibres for a group with only those; NaN without fibres).
  std::vector<double> groupMeanStretch, groupMeanContractileStretch;
};

// Evaluates the muscle point laws and the external fibres at the converged u, writes their
// lambda_c into `history`'s trial values (commit separately) and returns the fields. `history`
// is the one the assembler reads (results.muscleHistory(), here writable). Collective.
MuscleFields updateMuscleHistory(const ResultEvaluator &results, const Vector &u, model::MuscleHistory &history);

} // namespace glossa::assembly
