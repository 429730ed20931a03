#include "control/GeneticAlgorithmParameters.hpp"

#include "control/RangeCheck.hpp"

namespace glossa::control {

void GeneticAlgorithmParameters::validate(const std::string &prefix) const {
  using detail::kInf;
  using detail::requireInRange;
  if (geneType != GeneType::binary && geneType != GeneType::continuous)
    throw std::invalid_argument(prefix + "geneType is out of range: allowed binary or continuous");
  requireInRange(prefix + "populationSize", populationSize, 2, kInf);
  requireInRange(prefix + "generations", generations, 1, kInf);
  // At least one elite makes the best objective non-increasing; at least one child slot keeps
  // the search moving.
  requireInRange(prefix + "eliteCount", eliteCount, 1, populationSize - 1);
  requireInRange(prefix + "tournamentSize", tournamentSize, 1, populationSize);
  requireInRange(prefix + "crossoverRate", crossoverRate, 0.0, 1.0);
  requireInRange(prefix + "mutationRate", mutationRate, 0.0, 1.0);
  requireInRange(prefix + "mutationSigma", mutationSigma, 0.0, kInf, true, true);
  requireInRange(prefix + "geneResolution", geneResolution, 0.0, 0.5);
  requireInRange(prefix + "stagnationGenerations", stagnationGenerations, 0, kInf);
  requireInRange(prefix + "minImprovement", minImprovement, 0.0, kInf, false, true);
  requireInRange(prefix + "objectiveTolerance", objectiveTolerance, 0.0, kInf, false, true);
}

}  // namespace glossa::control
