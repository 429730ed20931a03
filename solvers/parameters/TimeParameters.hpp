#pragma once
// The deck's Time section, declared and parsed once: quasi-static load/time stepping with
// automatic cut-back (StepSizeController; history makes the problem time-dependent, so every
// step is solved at its own time), the predictor, the limit-point check and arc-length
// continuation.

#include <Teuchos_ParameterList.hpp>

#include "io/deck/Deck.hpp"

#include "solvers/stepping/StepSizeController.hpp"

namespace glossa::solvers {

enum class Predictor { automatic, none, linearExtrapolation };
enum class AtLimitPoint { stop, ignore, follow };
enum class PathFollowing { loadControl, arcLength };

struct TimeParameters {
  StepSizeRule steps; // end time, nominal and minimum step
  // The deck's own end time, which a ramp of duration 0 spans: the file's Time/end time (or the
  // default) even when --set changes the run's, so a shortened run shows the first part of the
  // load history the deck describes (deckEndTime).
  double rampEndTime = 1.0; // parseTimeParameters: the section's end time
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
// Time/end time as the deck file gives it (its default if it gives none), whatever --set made of
// it; a file value that is not a positive number (never validated, --set replaced it): the
// run's own end time.
double deckEndTime(const io::Deck &deck);

} // namespace glossa::solvers
