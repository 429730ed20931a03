#include "solvers/run/CheckpointContents.hpp"

#include <cmath>
#include <limits>

#include "io/output/CheckpointError.hpp"

namespace glossa::solvers {

nlohmann::json toJson(const OutputMark &mark) {
  nlohmann::json steps = nlohmann::json::array();
  for (const auto &step : mark.fieldSteps) {
    nlohmann::json attributes = nlohmann::json::array();
    for (const auto &a : step.attributes)
      attributes.push_back({a.name, a.components, a.center == io::Centering::Node ? "node" : "cell", a.dataset});
    steps.push_back({{"time", step.time}, {"attributes", attributes}});
  }
  return {{"csv_bytes", mark.csvBytes}, {"field_steps", steps}};
}

OutputMark outputMarkFromJson(const nlohmann::json &j) {
  OutputMark mark;
  mark.csvBytes = j.at("csv_bytes").get<std::map<std::string, std::uintmax_t>>();
  for (const auto &step : j.at("field_steps")) {
    io::XdmfStep s{step.at("time").get<double>(), {}};
    for (const auto &a : step.at("attributes"))
      s.attributes.push_back({a.at(0).get<std::string>(), a.at(1).get<int>(),
                              a.at(2).get<std::string>() == "node" ? io::Centering::Node : io::Centering::Cell,
                              a.at(3).get<std::string>()});
    mark.fieldSteps.push_back(std::move(s));
  }
  return mark;
}

nlohmann::json toJson(const model::MuscleHistory::Snapshot &h) {
  return {{"lambda_c", h.lambdaC}, {"alpha", h.alpha}, {"input", h.input}, {"external_lambda_c", h.externalLambdaC},
          {"time", h.time},        {"dt", h.dt}};
}

model::MuscleHistory::Snapshot muscleSnapshotFromJson(const nlohmann::json &j) {
  model::MuscleHistory::Snapshot h;
  h.lambdaC = j.at("lambda_c").get<std::vector<double>>();
  h.alpha = j.at("alpha").get<std::vector<double>>();
  h.input = j.at("input").get<std::vector<double>>();
  h.externalLambdaC = j.at("external_lambda_c").get<std::vector<std::vector<double>>>();
  h.time = j.at("time").get<double>();
  h.dt = j.at("dt").get<double>();
  return h;
}

// JSON has no NaN: a point without an anchor is written as anchored 0 with zero coordinates.
nlohmann::json toJson(const contact::ContactState::Snapshot &state) {
  std::vector<double> anchors(state.anchors.size(), 0.0), anchored(state.slip.size(), 0.0);
  for (std::size_t i = 0; i < anchored.size(); ++i) {
    if (!std::isfinite(state.anchors[3 * i])) continue;
    anchored[i] = 1.0;
    for (std::size_t k = 0; k < 3; ++k) anchors[3 * i + k] = state.anchors[3 * i + k];
  }
  return {{"multipliers", state.multipliers}, {"anchors", anchors}, {"anchored", anchored}, {"slip", state.slip}};
}

contact::ContactState::Snapshot contactSnapshotFromJson(const nlohmann::json &j) {
  contact::ContactState::Snapshot state;
  state.multipliers = j.at("multipliers").get<std::vector<double>>();
  state.gap.assign(state.multipliers.size(), std::numeric_limits<double>::infinity());
  state.pressure.assign(state.multipliers.size(), 0.0);
  state.anchors = j.at("anchors").get<std::vector<double>>();
  state.slip = j.at("slip").get<std::vector<double>>();
  const auto anchored = j.at("anchored").get<std::vector<double>>();
  for (std::size_t i = 0; i < anchored.size() && 3 * i + 2 < state.anchors.size(); ++i)
    if (anchored[i] == 0.0)
      for (std::size_t k = 0; k < 3; ++k) state.anchors[3 * i + k] = std::numeric_limits<double>::quiet_NaN();
  return state;
}

std::vector<double> ownedValues(const assembly::Vector &v) {
  const auto data = v.getData();
  return std::vector<double>(data.begin(), data.end());
}

void assignOwnedValues(assembly::Vector &v, const nlohmann::json &values, const char *what) {
  const auto x = values.get<std::vector<double>>();
  auto data = v.getDataNonConst();
  if (x.size() != static_cast<std::size_t>(data.size()))
    throw io::CheckpointError(std::string("the checkpoint's ") + what + " has " + std::to_string(x.size()) + " values here, " +
                          std::to_string(data.size()) + " expected (another mesh or partition)");
  std::copy(x.begin(), x.end(), data.begin());
}

std::vector<double> elementValues(const nlohmann::json &values, std::size_t expected, const char *what) {
  auto x = values.get<std::vector<double>>();
  if (x.size() != expected)
    throw io::CheckpointError(std::string("the checkpoint's ") + what + " has " + std::to_string(x.size()) +
                          " element values here, " + std::to_string(expected) + " expected (another mesh or partition)");
  return x;
}

} // namespace glossa::solvers
