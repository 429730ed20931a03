#include "solvers/incompressibility/MultiplierPredictor.hpp"

#include <stdexcept>
#include <string>

namespace glossa::solvers {

void MultiplierPredictor::predict(double dt, std::vector<double> &lambda) const {
  if (last_.size() != lambda.size()) return;
  lambda = last_;
  if (beforeLast_.size() != lambda.size() || !(lastDt_ > 0.0)) return;
  const double ratio = dt / lastDt_;
  for (std::size_t e = 0; e < lambda.size(); ++e) lambda[e] += ratio * (last_[e] - beforeLast_[e]);
}

void MultiplierPredictor::commit(const std::vector<double> &nextMultipliers, double dt) {
  if (nextMultipliers.empty()) {
    last_.clear();
    beforeLast_.clear();
    return;
  }
  beforeLast_ = std::move(last_);
  last_ = nextMultipliers;
  lastDt_ = dt;
}

nlohmann::json MultiplierPredictor::toJson() const {
  return {{"last", last_}, {"before_last", beforeLast_}, {"last_dt", lastDt_}};
}

void MultiplierPredictor::restore(const nlohmann::json &saved, std::size_t elements) {
  auto values = [&](const char *key) {
    std::vector<double> v = saved.at(key).get<std::vector<double>>();
    if (!v.empty() && v.size() != elements)
      throw std::invalid_argument(std::string("multiplier prediction '") + key + "': " + std::to_string(v.size()) +
                                  " values for " + std::to_string(elements) + " elements");
    return v;
  };
  last_ = values("last");
  beforeLast_ = values("before_last");
  lastDt_ = saved.at("last_dt").get<double>();
}

} // namespace glossa::solvers
