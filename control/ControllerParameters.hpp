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

struct ControllerParameters {
  ControllerType type = ControllerType::geneticAlgorithm;
  GeneticAlgorithmParameters ga;
  GaussNewtonParameters gradient;
  bool pruning = true;                       // search only the groups in tension (MusclePruning.hpp)
  double pruningTolerance = 0.0;             // lambdabar_M must exceed lambdabar_M^0 by more, [0, inf)
  std::vector<std::string> alwaysEvaluated;  // group names never pruned (the genioglossus parts)
  bool keepActiveGroups = true;              // a group with u > 0 at the previous step is never pruned
  bool seedWithPreviousBest = true;
  bool verifySensitivities = false;          // gradient: check S against differences of full solves          // the previous step's best joins generation 0

  // Throws std::invalid_argument naming the bad field ("ga.populationSize", "pruningTolerance",
  // "alwaysEvaluated[2]") and its allowed range.
  void validate() const;

  // Per group of `groupNames`: whether it is in alwaysEvaluated. Throws std::invalid_argument
  // naming an alwaysEvaluated entry that is not a group.
  std::vector<bool> alwaysEvaluatedMask(const std::vector<std::string> &groupNames) const;
};

}  // namespace glossa::control
