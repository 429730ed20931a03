#include "airflow/CentrelinePressure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace glossa::airflow {

CentrelinePressure::CentrelinePressure(std::vector<Eigen::Vector3d> centres, std::vector<double> arcLengths)
    : centres_(std::move(centres)), arcLengths_(std::move(arcLengths)) {
  if (centres_.empty() || centres_.size() != arcLengths_.size())
    throw std::invalid_argument("centreline pressure: " + std::to_string(centres_.size()) + " centres and " +
                                std::to_string(arcLengths_.size()) +
                                " arc lengths; one of each per section, at least one section");
  for (std::size_t i = 1; i < arcLengths_.size(); ++i)
    if (!(arcLengths_[i] > arcLengths_[i - 1]))
      throw std::invalid_argument("centreline pressure: the arc length of section " + std::to_string(i) +
                                  " does not exceed the one before; arc lengths must increase");
}

double CentrelinePressure::arcLengthOf(const Eigen::Vector3d &x) const {
  if (centres_.size() == 1) return arcLengths_[0];
  double best = std::numeric_limits<double>::infinity(), s = arcLengths_[0];
  for (std::size_t i = 0; i + 1 < centres_.size(); ++i) {
    const Eigen::Vector3d d = centres_[i + 1] - centres_[i];
    const double lengthSquared = d.squaredNorm();
    const double t = lengthSquared > 0.0 ? std::clamp((x - centres_[i]).dot(d) / lengthSquared, 0.0, 1.0) : 0.0;
    const double distance = (centres_[i] + t * d - x).squaredNorm();
    // Strictly nearer only: a point as near two segments (at their shared centre) keeps the first.
    if (distance < best) {
      best = distance;
      s = arcLengths_[i] + t * (arcLengths_[i + 1] - arcLengths_[i]);
    }
  }
  return s;
}

double CentrelinePressure::pressureAtArcLength(double s, const std::vector<double> &pressures,
                                               PressureMapping mapping) const {
  if (pressures.size() != arcLengths_.size())
    throw std::invalid_argument("centreline pressure: " + std::to_string(pressures.size()) + " pressures for " +
                                std::to_string(arcLengths_.size()) + " sections");
  const auto n = arcLengths_.size();
  if (s <= arcLengths_.front()) return pressures.front();
  if (s >= arcLengths_.back()) return pressures.back();
  // The segment [s_i, s_{i+1}] holding s.
  const std::size_t i = std::upper_bound(arcLengths_.begin(), arcLengths_.end(), s) - arcLengths_.begin() - 1;
  const double t = (s - arcLengths_[i]) / (arcLengths_[i + 1] - arcLengths_[i]);
  if (mapping == PressureMapping::nearestSection) return pressures[t <= 0.5 ? i : std::min(i + 1, n - 1)];
  return (1.0 - t) * pressures[i] + t * pressures[i + 1];
}

}  // namespace glossa::airflow
