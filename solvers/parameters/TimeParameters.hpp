#pragma once
// The deck's Time section, declared and parsed once: quasi-static load/time stepping with
// automatic cut-back (StepSizeController; history makes the problem time-dependent, so every
// step is solved at its own time), the predictor, the limit-point check and arc-length
// continuation.

#include <Teuchos_ParameterList.hpp>

#include "solvers/stepping/StepSizeController.hpp"

namespace glossa::solvers {

enum class Predictor { automatic, none, linearExtrapolation };
enum class AtLimitPoint { stop, ignore, follow };
enum class PathFollowing { loadControl, arcLength };

struct TimeParameters {
  StepSizeRule steps; // end time, nominal and minimum step
  Predictor predictor = Predictor::automatic;
  AtLimitPoint atLimitPoint = AtLimitPoint::stop;
  double limitPointTolerance = 0.01;
  PathFollowing pathFollowing = PathFollowing::loadControl;
  int arcLengthSteps = 200;
  double stopAtDisplacement = 0.0; // [m]; 0: none
};

Teuchos::ParameterList timeParameters();
// `section`: validated against timeParameters() (every default filled in).
TimeParameters parseTimeParameters(const Teuchos::ParameterList &section);

} // namespace glossa::solvers
