#pragma once
// The deck's Time section, declared and parsed once: quasi-static load/time stepping with
// automatic cut-back (StepSizeController; history makes the problem time-dependent, so every
// step is solved at its own time), the predictor, the limit-point check and arc-length
// continuation; with analysis = dynamic, inertia by generalized-alpha (doc/dynamics.md).

#include <array>
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "fem/HexMass.hpp"

#include "io/deck/Deck.hpp"

#include "solvers/stepping/StepSizeController.hpp"

namespace glossa::solvers {

enum class Predictor { automatic, none, linearExtrapolation };
enum class AtLimitPoint { stop, ignore, follow };
enum class PathFollowing { loadControl, arcLength };

enum class Analysis { quasiStatic, dynamic };
enum class Integrator { generalizedAlpha, backwardEuler, energyConserving };

// Time/analysis = dynamic: M a + C v + f_int(u) = f_ext by generalized-alpha (Chung & Hulbert
// 1993) with the high-frequency spectral radius rho_inf, Rayleigh damping C = alpha M + beta K_0
// (K_0 the tangent at the initial state) and an initial velocity field; or by backward Euler
// (first order, strongly dissipative, for stiff cases); or by the energy-conserving step (the
// trapezoidal rule with each element's force a discrete gradient of its stored energy).
struct DynamicsParameters {
  Analysis analysis = Analysis::quasiStatic;
  Integrator integrator = Integrator::generalizedAlpha;
  double spectralRadius = 1.0; // rho_inf in [0, 1]; 1: Newmark's trapezoidal rule
  fem::MassLumping mass = fem::MassLumping::consistent;
  double rayleighMass = 0.0;      // alpha [1/s]
  double rayleighStiffness = 0.0; // beta [s]
  // v_x, v_y, v_z at t = 0 as expressions of the reference position X, Y, Z [m/s]
  // (io::SpaceTimeExpression, checked by parseRunConfiguration).
  std::array<std::string, 3> initialVelocity{"0", "0", "0"};
  bool dynamic() const { return analysis == Analysis::dynamic; }
};

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
  DynamicsParameters dynamics;
};

Teuchos::ParameterList timeParameters();
// `section`: validated against timeParameters() (every default filled in).
TimeParameters parseTimeParameters(const Teuchos::ParameterList &section);
// Time/end time as the deck file gives it (its default if it gives none), whatever --set made of
// it; a file value that is not a positive number (never validated, --set replaced it): the
// run's own end time.
double deckEndTime(const io::Deck &deck);
// The dynamic parameters a static run would not read are refused, as are initial velocities
// that are not expressions of X, Y, Z: io::DeckError naming the file, line and what is allowed.
void checkDynamicsParameters(const io::Deck &deck, const DynamicsParameters &dynamics);

} // namespace glossa::solvers
