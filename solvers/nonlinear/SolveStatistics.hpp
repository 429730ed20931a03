#pragma once
// What a step's solve reports: each Newton solve's iterations and residual history, and the
// Uzawa loop around them. Plain structs without Trilinos, so that the control driver can carry a
// winning candidate's statistics and share them among control groups (ControlStepResult).

#include <string>
#include <vector>

#include "contact/ContactMeasures.hpp"

namespace glossa::solvers {

struct NewtonResult {
  bool converged = false;
  bool elementInverted = false;
  // Tightened the last solve (the Uzawa loop's inexact one met the volume, nothing moved between):
  // the same problem from its last iterate, its direct factors kept.
  bool continuesLastSolve = false;
  int iterations = 0;
  int linearIterations = 0;
  std::vector<double> residualNorms; // ||f|| before each iteration and at the end
  std::vector<int> linearIterationsPerStep;
  std::string failure; // why, when not converged for a reason other than the iteration limit
};

// In augmented-Lagrangian mode the error is |theta_e - theta_phys(p_e)| (the distance from the
// physical law; |theta_e - 1| for nu = 0.5); with a penalty it is |theta_e - 1|.
struct DilatationError {
  double max = 0.0;             // max over elements
  double mean = 0.0;            // reference-volume-weighted mean
  double maxVolumeChange = 0.0; // max over elements of |theta_e - 1|
};

struct UzawaResult {
  // Newton converged, (AL mode) the dilatation tolerance was met and every augmented contact's
  // gap tolerance too
  bool converged = false;
  bool elementInverted = false;
  int solves = 0;             // Newton solves = Uzawa iterations
  int newtonIterations = 0;
  int linearIterations = 0;
  DilatationError dilatation;
  std::vector<NewtonResult> newton;
  int augmentationRaises = 0; // times a tissue's kappa_AL was raised in this step (UzawaLoop)
  // Augmented Lagrangian, converged: the multipliers the loop's next update would set, beta p_e
  // (the next step's prediction starts from them: MultiplierPredictor).
  std::vector<double> nextMultipliers;
  // Per scene contact, at the last converged solve (its gaps recorded in the contact's state).
  std::vector<contact::ContactMeasures> contacts;
  int contactUpdates = 0; // Uzawa updates of contact multipliers in this step
  bool outerFailed = false; // the loop's outer condition (UzawaLoop::OuterCondition) failed
  bool gapMet() const {
    for (const auto &c : contacts)
      if (!c.gapMet()) return false;
    return true;
  }
};

} // namespace glossa::solvers
