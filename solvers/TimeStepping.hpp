#pragma once
// The Time section: quasi-static load/time stepping with automatic cut-back (StepSizeController;
// history makes the problem time-dependent, so every step is solved at its own time), the
// predictor and the limit-point check.

#include <Teuchos_ParameterList.hpp>

#include "solvers/StepSizeController.hpp"

namespace glossa::solvers {

Teuchos::ParameterList timeParameters();

// The Time section's step-size rule.
StepSizeRule stepSizeRule(const Teuchos::ParameterList &section);

} // namespace glossa::solvers
