#include "solvers/stepping/LimitPointMonitor.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace glossa::solvers {

double LimitPointMonitor::relativeStiffness(double s) {
  if (!std::isfinite(s)) return std::numeric_limits<double>::quiet_NaN();
  if (!(reference_ > 0.0)) {
    if (!(s > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    reference_ = s;
  }
  return s / reference_;
}

void LimitPointMonitor::accepted(double t, double S) {
  if (std::isfinite(S)) lastS_ = S;
  // A step beyond the bracket's upper end converged after all (a path that stiffens again):
  // what was bracketed was not a maximum of this path.
  if (bracket_ && t >= bracket_->upper) bracket_.reset();
}

void LimitPointMonitor::refused(double t, double trialTime, bool unstable, std::size_t node) {
  if (!unstable && !(lastS_ < kSoftened) && !bracket_) return;
  if (!bracket_ || trialTime <= bracket_->upper) {
    const bool wasUnstable = bracket_ && bracket_->unstable;
    bracket_ = Bracket{t, trialTime, unstable || wasUnstable, node};
  } else {
    bracket_->lower = t;
  }
}

std::string LimitPointMonitor::description(const Eigen::Vector3d &x) const {
  const Bracket &b = *bracket_;
  char text[512];
  std::snprintf(text, sizeof text,
                "a limit point of the load path between t = %.6g and %.6g s: the tangent's stiffness along the path "
                "fell to %.3g of the first step's%s; node %zu (reference position %.4g, %.4g, %.4g) moves most "
                "there. Past a maximum of the load there is no equilibrium nearby under load control: drive the path "
                "by a displacement instead",
                b.lower, b.upper, lastS_,
                b.unstable ? " and the states past it converged unstable (negative stiffness)" : " and Newton found no state past it",
                b.node, x.x(), x.y(), x.z());
  return text;
}

nlohmann::json LimitPointMonitor::record(const Eigen::Vector3d &x) const {
  const Bracket &b = *bracket_;
  return {{"time", b.lower},
          {"bracket", {b.lower, b.upper}},
          {"relative_stiffness", lastS_},
          {"unstable_states_found", b.unstable},
          {"node", b.node},
          {"reference_position", {x.x(), x.y(), x.z()}}};
}

nlohmann::json LimitPointMonitor::state() const {
  nlohmann::json s = {{"reference", reference_}, {"last", lastS_}};
  if (bracket_) s["bracket"] = {bracket_->lower, bracket_->upper, bracket_->unstable ? 1.0 : 0.0, static_cast<double>(bracket_->node)};
  return s;
}

void LimitPointMonitor::restore(const nlohmann::json &s) {
  reference_ = s.at("reference").get<double>();
  lastS_ = s.at("last").get<double>();
  bracket_.reset();
  if (!s.contains("bracket")) return;
  const auto b = s.at("bracket").get<std::vector<double>>();
  bracket_ = Bracket{b.at(0), b.at(1), b.at(2) != 0.0, static_cast<std::size_t>(b.at(3))};
}

} // namespace glossa::solvers
