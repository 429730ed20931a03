#pragma once
// The parameters of the controller of a control step (paper §6.1): the search (GA or gradient)
// and the muscle pruning. A plain struct with defaults; the deck section fills it and calls validate().

#include <string>
#include <vector>

#include "control/GaussNewtonController.hpp"
#include "control/GeneticAlgorithmParameters.hpp"

namespace glossa::control {

// The search of a control step: the paper's elitist GA, or the projected Gauss-Newton iteration
// on the tangent's sensitivities (GaussNewtonController.hpp).
enum class ControllerType { geneticAlgorithm, gradient };

// The GA's prediction seed (paper §6.1: generation 0 holds "a prediction for the solution based on
// previous steps"). extrapolation: 2 u_{k-1} - u_{k-2} of the last two found steps (InputPrediction.hpp),
// so a search on a rising or falling load starts where it is heading. gaussNewtonStep: one
// bounded, linearised step from the previous best (the gradient controller's first iteration:
// one full solve and one sensitivity), which also sees a load that starts to change, e.g. at the
// onset of a breath, where extrapolating from rest predicts rest.
enum class PredictionSeed { none, extrapolation, gaussNewtonStep };

// The gradient controller's sensitivity tangent (ControllerParameters::sensitivityTangent).
enum class SensitivityTangent { automatic, constrained, inner };

struct ControllerParameters {
  ControllerType type = ControllerType::geneticAlgorithm;
  GeneticAlgorithmParameters ga;
  GaussNewtonParameters gradient;
  bool pruning = true;                       // search only the groups in tension (MusclePruning.hpp)
  double pruningTolerance = 0.0;             // lambdabar_M must exceed lambdabar_M^0 by more, [0, inf)
  std::vector<std::string> alwaysEvaluated;  // group names never pruned (the genioglossus parts)
  bool keepActiveGroups = true;              // a group with u > 0 at the previous step is never pruned
  bool seedWithPreviousBest = true;          // the previous step's best joins generation 0
  // GA: a prediction joins generation 0 after the previous best (PredictionSeed).
  PredictionSeed predictionSeed = PredictionSeed::none;
  // gaussNewtonStep: the prediction at k step lengths 1, 1/2, ..., 2^(1-k) of the linearised step,
  // k seeds; generation 0 then holds a line search along it. Where the response is strongly
  // nonlinear (the hyoid muscles supine) the full step overshoots and loses to the previous best,
  // and a short GA ends on it; a shorter step along the same direction still improves. [1, 16]
  int predictionSeedSteps = 1;
  // epsilon [m]: the price of activation, so that among inputs that hold the points equally well
  // the one with the least activation wins (redundant muscles make eq. 25's minimiser a valley).
  // The GA ranks by eq. 25 + epsilon sum_M u_M^2; the gradient controller minimises
  // sum_p |r_p|^2 + epsilon^2 sum_M u_M^2 (the residual stacked with epsilon u). 0: eq. 25 alone.
  double effortWeight = 0.0;
  bool verifySensitivities = false;          // gradient: check S against differences of full solves
  // gradient: a candidate's solve starts from the accepted state moved along its sensitivities,
  // x_a + (dx/du)(u - u_a), with the accepted state's multipliers, instead of from the step's
  // start (a failed start there is retried from the step's start). The GA's candidates always start
  // from the step's start, so that control groups agree (doc/control.md, "Where a candidate starts").
  bool predictedStart = true;
  // GA: a candidate whose moved start turns an element over (at the start or on Newton's way
  // from it) is solved again from the step's start (true), or ranked as failed (false). Such
  // candidates lie far from the seed's inputs; on the s8_5 GA decks none of them came near the
  // step's best, and their solves from the step's start cost a quarter of the Newton iterations
  // (doc/control.md, "Where a candidate starts").
  bool retryTurnedOverStarts = true;
  // gradient: the tangent of its sensitivities under the augmented Lagrangian (doc/control.md,
  // "The sensitivities"). constrained: the physical bulk modulus capped at sensitivityPenaltyRatio
  // mu, the multipliers following the pressures (the converged loop's linearisation, to order
  // S / (ratio mu), S an element's own stiffness against a volume change). inner: the Newton
  // solves' own, kappa_t at fixed multipliers (an error of order S / kappa_AL), which the GA's
  // prediction seed always uses. automatic: constrained with a direct linear solve, inner with an
  // iterative one, where the stiffer tangent costs more Krylov iterations than it saves solves.
  SensitivityTangent sensitivityTangent = SensitivityTangent::automatic;
  double sensitivityPenaltyRatio = 1e3; // [1, 1e8]
  // The airway term (doc/control.md, "The airway term"): w_A max(0, A_open - A) joins eq. 25 in
  // the objective, A the smallest lumen area of the candidate's state (doc/airway.md); w_A [1/m]
  // makes it a length, as eq. 25 is. The gradient controller's residual gains the row itself and
  // its sensitivity -w_A dA/du. 0: no airway term.
  double airwayWeight = 0.0;     // w_A [1/m], >= 0
  double airwayOpenArea = 0.0;   // A_open [m^2], > 0 when airwayWeight > 0

  // Throws std::invalid_argument naming the bad field ("ga.populationSize", "pruningTolerance",
  // "alwaysEvaluated[2]") and its allowed range.
  void validate() const;

  // Per group of `groupNames`: whether it is in alwaysEvaluated. Throws std::invalid_argument
  // naming an alwaysEvaluated entry that is not a group.
  std::vector<bool> alwaysEvaluatedMask(const std::vector<std::string> &groupNames) const;
};

}  // namespace glossa::control
