#include "contact/ContactState.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace glossa::contact {

ContactState::ContactState(std::size_t faces)
    : committed_(faces * kPointsPerFace, 0.0),
      trial_(faces * kPointsPerFace, 0.0),
      // Nothing evaluated yet: no point is known to be near the obstacle.
      gap_(faces * kPointsPerFace, std::numeric_limits<double>::infinity()),
      pressure_(faces * kPointsPerFace, 0.0) {}

FaceMultipliers ContactState::get(const std::vector<double> &values, std::size_t face) const {
  FaceMultipliers lambda;
  std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(face * kPointsPerFace), kPointsPerFace, lambda.begin());
  return lambda;
}

void ContactState::record(std::size_t face, const FaceContactPoints &points) {
  for (std::size_t q = 0; q < kPointsPerFace; ++q) {
    gap_[face * kPointsPerFace + q] = points[q].gap;
    pressure_[face * kPointsPerFace + q] = points[q].pressure;
  }
}

ContactPointState ContactState::point(std::size_t face, std::size_t q) const {
  return {gap_[face * kPointsPerFace + q], pressure_[face * kPointsPerFace + q]};
}

void ContactState::updateMultipliers(double penalty) {
  for (std::size_t i = 0; i < trial_.size(); ++i) trial_[i] = updatedMultiplier(trial_[i], penalty, gap_[i]);
}

double ContactState::largestGapError() const {
  double largest = 0.0;
  for (std::size_t i = 0; i < gap_.size(); ++i) largest = std::max(largest, gapError({gap_[i], pressure_[i]}));
  return largest;
}

double ContactState::largestPenetration() const {
  double largest = 0.0;
  for (std::size_t i = 0; i < gap_.size(); ++i)
    if (pressure_[i] > 0) largest = std::max(largest, -gap_[i]);
  return largest;
}

void ContactState::restore(const Snapshot &snapshot) {
  const std::size_t n = snapshot.multipliers.size();
  if (snapshot.gap.size() != n || snapshot.pressure.size() != n || n % kPointsPerFace != 0)
    throw std::invalid_argument("contact state: " + std::to_string(n) + " multipliers, " +
                                std::to_string(snapshot.gap.size()) + " gaps and " +
                                std::to_string(snapshot.pressure.size()) +
                                " pressures; expected equal counts, 4 per contact face");
  committed_ = trial_ = snapshot.multipliers;
  gap_ = snapshot.gap;
  pressure_ = snapshot.pressure;
}

}  // namespace glossa::contact
