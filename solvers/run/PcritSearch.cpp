#include "solvers/run/PcritSearch.hpp"

#include <cmath>
#include <cstdio>
#include <utility>

namespace glossa::solvers {

PcritSearch::PcritSearch(const model::AirwayOutput &airway, loads::PressureField pressure, std::string loadName)
    : airway_(airway), pressure_(std::move(pressure)), loadName_(std::move(loadName)) {}

std::optional<int> PcritSearch::closedSection(const std::vector<Eigen::Vector3d> &positions) const {
  const airway::LumenState state = airway_.lumen->measure(positions);
  std::optional<int> found;
  for (std::size_t k = 0; k < state.sections.size(); ++k) {
    const airway::SectionState &s = state.sections[k];
    if (s.closed && (!found || s.area() < state.sections[static_cast<std::size_t>(*found)].area()))
      found = static_cast<int>(k);
  }
  return found;
}

void PcritSearch::opened(double t) {
  if (high_) ++bisectionSteps_;
  low_ = t;
}

void PcritSearch::closed(double t, int section) {
  if (high_) ++bisectionSteps_;
  high_ = t;
  section_ = section;
}

bool PcritSearch::found() const {
  return high_ && std::abs(pressure(*high_) - pressure(low_)) <= airway_.pressureTolerance;
}

nlohmann::json PcritSearch::summary(double reached, double endTime) const {
  nlohmann::json j = {{"load", loadName_}, {"tolerance_Pa", airway_.pressureTolerance}};
  if (!high_) {
    j["closed"] = false;
    j["largest_suction_Pa"] = pressure(reached);
    j["largest_suction_cmH2O"] = pressure(reached) / kPascalPerCmH2O;
    j["deck_largest_suction_Pa"] = pressure(endTime);
    return j;
  }
  // The open end and the closed end, numerically ordered (suction is negative: the closed end is
  // the lower); Pcrit is the bracket's middle.
  const double pOpen = pressure(low_), pClosed = pressure(*high_);
  const double lo = std::min(pOpen, pClosed), hi = std::max(pOpen, pClosed), mid = 0.5 * (lo + hi);
  const auto &arc = airway_.lumen->centreline().arcLength;
  j.update({{"closed", true},
            {"bracketed", found()},
            {"cmH2O", mid / kPascalPerCmH2O},
            {"low_cmH2O", lo / kPascalPerCmH2O},
            {"high_cmH2O", hi / kPascalPerCmH2O},
            {"Pa", mid},
            {"low_Pa", lo},
            {"high_Pa", hi},
            {"open_Pa", pOpen},
            {"closed_Pa", pClosed},
            {"time_open", low_},
            {"time_closed", *high_},
            {"section", section_},
            {"section_arc_length", arc[static_cast<std::size_t>(section_)]},
            {"bisection_solves", bisectionSteps_}});
  return j;
}

std::string PcritSearch::line(double reached, double endTime) const {
  char s[320];
  if (!high_)
    std::snprintf(s, sizeof s, "airway: never closed up to %.4g Pa (%.4g cmH2O) of '%s'%s; no Pcrit",
                  pressure(reached), pressure(reached) / kPascalPerCmH2O, loadName_.c_str(),
                  pressure(reached) == pressure(endTime) ? "" : ", where the run stopped short of the deck's largest");
  else {
    const nlohmann::json j = summary(reached, endTime);
    std::snprintf(s, sizeof s,
                  "airway: Pcrit = %.4f cmH2O (%.2f Pa), bracket [%.4f, %.4f] cmH2O%s, section %d at %.2f mm, "
                  "%d bisection solves",
                  j["cmH2O"].get<double>(), j["Pa"].get<double>(), j["low_cmH2O"].get<double>(),
                  j["high_cmH2O"].get<double>(), found() ? "" : " (not narrowed to the tolerance)", section_,
                  1e3 * j["section_arc_length"].get<double>(), bisectionSteps_);
  }
  return s;
}

} // namespace glossa::solvers
