#include "solvers/stepping/StepSizeController.hpp"

#include <algorithm>

namespace glossa::solvers {

StepSizeController::StepSizeController(const StepSizeRule &rule)
    : rule_{rule.endTime, std::min(rule.nominal, rule.endTime), rule.minimum}, dt_(rule_.nominal) {}

double StepSizeController::nextStep(double t) const {
  const double remaining = rule_.endTime - t;
  return remaining < 1.0001 * dt_ ? remaining : dt_;
}

bool StepSizeController::cutBack() {
  successes_ = 0;
  dt_ *= 0.5;
  return dt_ >= rule_.minimum;
}

void StepSizeController::accept() {
  if (++successes_ >= 2 && dt_ < rule_.nominal) {
    dt_ = std::min(2.0 * dt_, rule_.nominal);
    successes_ = 0;
  }
}

} // namespace glossa::solvers
