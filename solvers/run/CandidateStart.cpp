#include "solvers/run/CandidateStart.hpp"

namespace glossa::solvers {

void CandidateStart::forget() {
  responses_ = Teuchos::null;
  pressureResponses_.clear();
}

void CandidateStart::record(const std::vector<double> &inputs, const std::vector<int> &groups,
                            const Teuchos::RCP<const assembly::MultiVector> &responses, std::vector<double> pressure,
                            std::vector<std::vector<double>> pressureResponses) {
  inputs_ = inputs;
  groups_ = groups;
  responses_ = responses;
  pressure_ = std::move(pressure);
  pressureResponses_ = std::move(pressureResponses);
}

void CandidateStart::predict(const std::vector<double> &inputs, const UzawaLoop &uzawa, StepState &start) const {
  assembly::ElementFields predicted;
  predicted.pressure = pressure_;
  for (std::size_t j = 0; j < groups_.size(); ++j) {
    const auto g = static_cast<std::size_t>(groups_[j]);
    const double change = inputs[g] - inputs_[g];
    if (change == 0.0) continue;
    start.u.update(change, *responses_->getVector(j), 1.0);
    if (pressureResponses_.empty()) continue;
    for (std::size_t i = 0; i < predicted.pressure.size(); ++i) predicted.pressure[i] += change * pressureResponses_[j][i];
  }
  if (!pressureResponses_.empty()) start.lambda = uzawa.nextMultipliers(predicted);
}

std::vector<std::vector<double>> elementPressureResponses(const assembly::ResultEvaluator &results,
                                                          const assembly::Vector &u, const std::vector<double> &lambda,
                                                          const assembly::MultiVector &responses) {
  // A thousandth of a unit input: small enough that the difference is the derivative, large
  // enough that the pressures' round-off (1e-16 of them) over 2 epsilon stays near 1e-13.
  const double epsilon = 1e-3;
  std::vector<std::vector<double>> out;
  for (std::size_t j = 0; j < responses.getNumVectors(); ++j) {
    assembly::Vector plus(u, Teuchos::Copy), minus(u, Teuchos::Copy);
    plus.update(epsilon, *responses.getVector(j), 1.0);
    minus.update(-epsilon, *responses.getVector(j), 1.0);
    const std::vector<double> pPlus = results.elementDilatations(plus, lambda).pressure;
    const std::vector<double> pMinus = results.elementDilatations(minus, lambda).pressure;
    std::vector<double> dp(pPlus.size());
    for (std::size_t i = 0; i < dp.size(); ++i) dp[i] = (pPlus[i] - pMinus[i]) / (2.0 * epsilon);
    out.push_back(std::move(dp));
  }
  return out;
}

} // namespace glossa::solvers
