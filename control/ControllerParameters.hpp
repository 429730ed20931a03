#pragma once
// The parameters of the GA controller of a control step (paper §6.1): the GA itself and the
// muscle pruning. A plain struct with defaults; the deck section fills it and calls validate().

#include <string>
#include <vector>

#include "control/GeneticAlgorithmParameters.hpp"

namespace glossa::control {

struct ControllerParameters {
  GeneticAlgorithmParameters ga;
  bool pruning = true;                       // search only the groups in tension (MusclePruning.hpp)
  double pruningTolerance = 0.0;             // lambdabar_M must exceed lambdabar_M^0 by more, [0, inf)
  std::vector<std::string> alwaysEvaluated;  // group names never pruned (the genioglossus parts)
  bool seedWithPreviousBest = true;          // the previous step's best joins generation 0

  // Throws std::invalid_argument naming the bad field ("ga.populationSize", "pruningTolerance",
  // "alwaysEvaluated[2]") and its allowed range.
  void validate() const;

  // Per group of `groupNames`: whether it is in alwaysEvaluated. Throws std::invalid_argument
  // naming an alwaysEvaluated entry that is not a group.
  std::vector<bool> alwaysEvaluatedMask(const std::vector<std::string> &groupNames) const;
};

}  // namespace glossa::control
