#pragma once
// The multipliers a load step's Uzawa loop starts from (augmented Lagrangian). The converged
// multipliers Lambda of a step lag its element pressures by the last update's worth (the loop
// stops as soon as the dilatation error is below the tolerance), so the next step starts from the
// update the loop would have made next, Lambda* = beta p (AugmentedLagrangianRule), extrapolated
// linearly in time from the step before:
//   Lambda_0(t + dt) = Lambda*_n + dt / dt_n (Lambda*_n - Lambda*_(n-1)).
// With it the first, inexact solve of a step often meets the dilatation tolerance already and the
// multiplier update after it is skipped (UzawaLoop): on the step-44 block 4 Newton iterations per
// step instead of 5 in most steps (bench/LOG.md, 2026-12-04 evening).
//
// Per local element; no Trilinos. Kept in checkpoints so that a restarted run predicts as the
// uninterrupted one did.

#include <vector>

#include <nlohmann/json.hpp>

namespace glossa::solvers {

class MultiplierPredictor {
public:
  // The start of the step to t + dt: `lambda` (the committed multipliers on entry) replaced by the
  // prediction, once a step has been committed with its updated multipliers.
  void predict(double dt, std::vector<double> &lambda) const;
  // A step of length dt committed, with the multipliers its next update would set (empty: none,
  // e.g. a penalty or mixed solve, and the prediction stops until the next).
  void commit(const std::vector<double> &nextMultipliers, double dt);

  nlohmann::json toJson() const;
  // A checkpoint's; throws std::invalid_argument if its sizes are not `elements`.
  void restore(const nlohmann::json &saved, std::size_t elements);

private:
  std::vector<double> last_, beforeLast_; // Lambda* of the last two committed steps
  double lastDt_ = 0.0;                   // the step between them
};

} // namespace glossa::solvers
