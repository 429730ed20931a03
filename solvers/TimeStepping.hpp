#pragma once
// Quasi-static load/time stepping with automatic cut-back: a failed step (Newton divergence,
// an inverted element, Uzawa not converging) is retried from the last committed state with
// half the step, and the step grows back after successes (DESIGN.md §1: history makes the
// problem time-dependent, so every step is solved at its own time).

#include <Teuchos_ParameterList.hpp>

namespace glossa::solvers {

Teuchos::ParameterList timeParameters();

class StepSizeController {
public:
  explicit StepSizeController(const Teuchos::ParameterList &section);

  double endTime() const { return endTime_; }
  // The next step from time t: never past the end time.
  double nextStep(double t) const;
  // After a failure: halve; false if the step would fall below the minimum.
  bool cutBack();
  // After a success: grow back (x2 after two successes in a row) up to the nominal step.
  void accept();
  double stepSize() const { return dt_; }
  double nominalStep() const { return nominal_; }

private:
  double endTime_, nominal_, minimum_, dt_;
  int successes_ = 0;
};

} // namespace glossa::solvers
