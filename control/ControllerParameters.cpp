#include "control/ControllerParameters.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "control/RangeCheck.hpp"

namespace glossa::control {

void ControllerParameters::validate() const {
  ga.validate("ga.");
  gradient.validate("gradient.");
  detail::requireInRange("pruningTolerance", pruningTolerance, 0.0, detail::kInf, false, true);
  detail::requireInRange("predictionSeedSteps", predictionSeedSteps, 1, 16);
  detail::requireInRange("effortWeight", effortWeight, 0.0, detail::kInf, false, true);
  detail::requireInRange("airwayWeight", airwayWeight, 0.0, detail::kInf, false, true);
  detail::requireInRange("airwayOpenArea", airwayOpenArea, 0.0, detail::kInf, false, true);
  detail::requireInRange("sensitivityPenaltyRatio", sensitivityPenaltyRatio, 1.0, 1e8);
  if (airwayWeight > 0.0 && !(airwayOpenArea > 0.0))
    throw std::invalid_argument("airwayOpenArea = 0 with airwayWeight > 0: allowed an area > 0 for the airway term");
  std::set<std::string> seen;
  for (std::size_t i = 0; i < alwaysEvaluated.size(); ++i) {
    const std::string field = "alwaysEvaluated[" + std::to_string(i) + "]";
    if (alwaysEvaluated[i].empty())
      throw std::invalid_argument(field + " is empty: allowed a muscle group name");
    if (!seen.insert(alwaysEvaluated[i]).second)
      throw std::invalid_argument(field + " = '" + alwaysEvaluated[i] + "' is listed twice");
  }
}

std::vector<bool> ControllerParameters::alwaysEvaluatedMask(
    const std::vector<std::string> &groupNames) const {
  std::vector<bool> mask(groupNames.size(), false);
  for (std::size_t i = 0; i < alwaysEvaluated.size(); ++i) {
    const auto it = std::find(groupNames.begin(), groupNames.end(), alwaysEvaluated[i]);
    if (it == groupNames.end())
      throw std::invalid_argument("alwaysEvaluated[" + std::to_string(i) + "] = '" + alwaysEvaluated[i] +
                                  "' is not a muscle group");
    mask[static_cast<std::size_t>(it - groupNames.begin())] = true;
  }
  return mask;
}

}  // namespace glossa::control
