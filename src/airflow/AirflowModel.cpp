#include "airflow/AirflowModel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "airflow/SectionMarch.hpp"
#include "materials/BracketedNewtonSolver.hpp"

namespace glossa::airflow {
namespace {

std::string sectionName(int i, const ChannelSection &s) {
  return "section " + std::to_string(i) + " (arc length " + std::to_string(s.arcLength) + " m)";
}

void checkChannel(const Channel &channel, const AirSettings &air) {
  if (channel.size() < 2)
    throw std::invalid_argument("airflow: the channel needs at least 2 sections, has " + std::to_string(channel.size()));
  for (std::size_t i = 0; i < channel.size(); ++i) {
    const ChannelSection &s = channel[i];
    const std::string name = sectionName(static_cast<int>(i), s);
    if (!std::isfinite(s.arcLength)) throw std::invalid_argument("airflow: " + name + ": arc length is not finite");
    if (i > 0 && !(s.arcLength > channel[i - 1].arcLength))
      throw std::invalid_argument("airflow: " + name + ": arc lengths must increase along the channel");
    if (!std::isfinite(s.area) || s.area < 0.0)
      throw std::invalid_argument("airflow: " + name + ": area " + std::to_string(s.area) +
                                  " m^2; allowed: finite and >= 0 (an unmeasured section is left out)");
    if (!std::isfinite(s.compliance) || s.compliance < 0.0)
      throw std::invalid_argument("airflow: " + name + ": compliance " + std::to_string(s.compliance) +
                                  " m^2/Pa; allowed: finite and >= 0");
  }
  if (!(air.density > 0.0) || !std::isfinite(air.density))
    throw std::invalid_argument("airflow: air density " + std::to_string(air.density) + " kg/m^3; allowed: > 0");
  if (!(air.viscosity >= 0.0) || !std::isfinite(air.viscosity))
    throw std::invalid_argument("airflow: air viscosity " + std::to_string(air.viscosity) + " Pa s; allowed: >= 0");
  if (!(air.recoveryCoefficient >= 0.0 && air.recoveryCoefficient <= 1.0))
    throw std::invalid_argument("airflow: recovery coefficient " + std::to_string(air.recoveryCoefficient) +
                                "; allowed: 0 to 1");
}

void requireFinite(double v, const char *what) {
  if (!std::isfinite(v)) throw std::invalid_argument(std::string("airflow: the ") + what + " is not finite");
}

// The channel seen from its other end: sections in reverse order, arc lengths from that end.
Channel reversedChannel(const Channel &channel) {
  Channel r(channel.rbegin(), channel.rend());
  const double end = channel.back().arcLength;
  for (auto &s : r) s.arcLength = end - s.arcLength;
  return r;
}

// The static pressures at flow rate Q >= 0 with p_0 = upstream - entry drop.
std::vector<double> marchFrom(double upstream, const SectionDrops &d) {
  std::vector<double> p(d.rise.size() + 1);
  p[0] = upstream - d.entry;
  for (std::size_t j = 0; j < d.rise.size(); ++j) p[j + 1] = p[j] + d.rise[j];
  return p;
}

double waveSpeedLimitOf(const Channel &channel, double density, int *section) {
  double limit = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < channel.size(); ++i) {
    const ChannelSection &s = channel[i];
    if (s.compliance <= 0.0) continue;
    // The speed index u/c = 1 with the wave speed c^2 = A / (rho dA/dp), u = Q/A.
    const double q = s.area * std::sqrt(s.area / (density * s.compliance));
    if (q < limit) {
      limit = q;
      if (section) *section = static_cast<int>(i);
    }
  }
  return limit;
}

// A solution in the reversed channel's order brought back to the nasal-to-tracheal order.
FlowSolution unreversed(FlowSolution s) {
  const int n = static_cast<int>(s.pressure.size());
  std::reverse(s.pressure.begin(), s.pressure.end());
  s.flowRate = -s.flowRate;
  std::swap(s.nasalPressure, s.trachealPressure);
  if (s.throat >= 0) s.throat = n - 1 - s.throat;
  if (s.chokeSection >= 0) s.chokeSection = n - 1 - s.chokeSection;
  return s;
}

}  // namespace

AirflowModel::AirflowModel(Channel channel, AirSettings air) : channel_(std::move(channel)), air_(air) {
  checkChannel(channel_, air_);
  for (int i = 0; i < static_cast<int>(channel_.size()); ++i)
    if (channel_[i].closed || channel_[i].area <= 0.0) {
      if (firstClosed_ < 0) firstClosed_ = i;
      lastClosed_ = i;
    }
  reversed_ = reversedChannel(channel_);
}

double AirflowModel::waveSpeedLimit(int *section) const { return waveSpeedLimitOf(channel_, air_.density, section); }

FlowSolution AirflowModel::closedSolution(double nasalPressure, double trachealPressure) const {
  FlowSolution s;
  s.closed = true;
  s.firstClosed = firstClosed_;
  s.lastClosed = lastClosed_;
  s.nasalPressure = nasalPressure;
  s.trachealPressure = trachealPressure;
  s.pressure.resize(channel_.size());
  for (int i = 0; i < static_cast<int>(channel_.size()); ++i)
    s.pressure[i] = i < firstClosed_ ? nasalPressure
                    : i > lastClosed_ ? trachealPressure
                                      : 0.5 * (nasalPressure + trachealPressure);
  return s;
}

FlowSolution AirflowModel::drivenFlow(const Channel &directed, double upstream, double downstream) const {
  FlowSolution s;
  s.throat = throatOf(directed);
  s.nasalPressure = upstream;
  s.trachealPressure = downstream;
  const double dp = upstream - downstream;
  double Q = 0.0;
  if (dp > 0.0) {
    // The drop entry - sum(rise) is at least rho Q^2 / (2 A_max^2) (the dynamic pressure of the
    // widest section is never recovered), so it reaches dp by Qmax: the root lies in [0, Qmax].
    // Solved for x = Q/Qmax with the residual in units of dp, so the tolerances are relative.
    double widest = 0.0;
    for (const auto &c : directed) widest = std::max(widest, c.area);
    const double Qmax = widest * std::sqrt(2.0 * dp / air_.density);
    auto residual = [&](double x) {
      const SectionDrops d = sectionDrops(directed, air_, s.throat, x * Qmax);
      double drop = d.entry, slope = d.entrySlope;
      for (std::size_t j = 0; j < d.rise.size(); ++j) {
        drop -= d.rise[j];
        slope -= d.riseSlope[j];
      }
      return materials::ValueSlope{(drop - dp) / dp, slope * Qmax / dp};
    };
    materials::ScalarSolveOptions options;
    options.xTolerance = 1e-15;
    options.residualTolerance = 1e-14;
    // The drop is convex and increasing in Q: Newton from the top of the bracket never leaves it.
    const auto root = materials::BracketedNewtonSolver(options).solve(residual, 0.0, 1.0, 1.0);
    if (root.status != materials::ScalarSolveStatus::Converged)
      throw std::runtime_error(std::string("airflow: the flow-rate solve failed: ") + materials::describe(root.status));
    Q = root.x * Qmax;
    s.iterations = root.iterations;
  }
  int choke = -1;
  const double limit = waveSpeedLimitOf(directed, air_.density, &choke);
  if (Q > limit) {
    Q = limit;
    s.choked = true;
    s.chokeSection = choke;
  }
  s.flowRate = Q;
  s.pressure = marchFrom(upstream, sectionDrops(directed, air_, s.throat, Q));
  if (s.choked) s.chokeDrop = s.pressure.back() - downstream;
  return s;
}

FlowSolution AirflowModel::withPressures(double nasalPressure, double trachealPressure) const {
  requireFinite(nasalPressure, "nasal pressure");
  requireFinite(trachealPressure, "tracheal pressure");
  if (firstClosed_ >= 0) return closedSolution(nasalPressure, trachealPressure);
  if (nasalPressure >= trachealPressure) return drivenFlow(channel_, nasalPressure, trachealPressure);
  return unreversed(drivenFlow(reversed_, trachealPressure, nasalPressure));
}

FlowSolution AirflowModel::withFlowRate(double nasalPressure, double flowRate) const {
  requireFinite(nasalPressure, "nasal pressure");
  requireFinite(flowRate, "flow rate");
  if (firstClosed_ >= 0) {
    if (flowRate != 0.0)
      throw std::domain_error("airflow: a flow rate of " + std::to_string(flowRate) + " m^3/s cannot pass " +
                              sectionName(firstClosed_, channel_[firstClosed_]) + ", which is closed");
    return closedSolution(nasalPressure, nasalPressure);
  }
  int choke = -1;
  const double limit = waveSpeedLimit(&choke);
  if (std::abs(flowRate) > limit)
    throw std::domain_error("airflow: a flow rate of " + std::to_string(flowRate) +
                            " m^3/s is above the wave-speed limit " + std::to_string(limit) + " m^3/s of " +
                            sectionName(choke, channel_[choke]));
  const bool forward = flowRate >= 0.0;
  const Channel &directed = forward ? channel_ : reversed_;
  FlowSolution s;
  s.throat = throatOf(directed);
  s.flowRate = std::abs(flowRate);
  const SectionDrops d = sectionDrops(directed, air_, s.throat, s.flowRate);
  if (forward) {
    s.pressure = marchFrom(nasalPressure, d);
    s.nasalPressure = nasalPressure;
    s.trachealPressure = s.pressure.back();
    return s;
  }
  // Towards the nose the nasal pressure is the static pressure of the reversed channel's last
  // section: march back from it, and the tracheal reservoir is the first section's plus the entry drop.
  const std::vector<double> fromZero = marchFrom(0.0, d);
  s.pressure.resize(fromZero.size());
  for (std::size_t i = 0; i < fromZero.size(); ++i) s.pressure[i] = fromZero[i] - fromZero.back() + nasalPressure;
  s.nasalPressure = s.pressure.front() + d.entry;  // the reservoir upstream in the reversed channel
  s.trachealPressure = nasalPressure;
  return unreversed(s);
}

}  // namespace glossa::airflow
