#include "contact/ContactState.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace glossa::contact {

ContactState::ContactState(std::size_t faces, std::size_t pointsPerFace)
    : pointsPerFace_(pointsPerFace),
      committed_(faces * pointsPerFace, 0.0),
      trial_(faces * pointsPerFace, 0.0),
      // Nothing evaluated yet: no point is known to be near the obstacle.
      gap_(faces * pointsPerFace, std::numeric_limits<double>::infinity()),
      pressure_(faces * pointsPerFace, 0.0) {
  if (pointsPerFace == 0) throw std::invalid_argument("contact state: 0 points per face");
}

FaceMultipliers ContactState::get(const std::vector<double> &values, std::size_t face) const {
  FaceMultipliers lambda;
  if (pointsPerFace_ != kPointsPerFace)
    throw std::logic_error("contact state: four multipliers asked of a face with " + std::to_string(pointsPerFace_) +
                           " points");
  std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(face * kPointsPerFace), kPointsPerFace, lambda.begin());
  return lambda;
}

void ContactState::record(std::size_t face, const FaceContactPoints &points) {
  for (std::size_t q = 0; q < kPointsPerFace; ++q) record(face, q, points[q]);
}

void ContactState::record(std::size_t face, std::size_t q, const ContactPointState &point) {
  gap_[face * pointsPerFace_ + q] = point.gap;
  pressure_[face * pointsPerFace_ + q] = point.pressure;
}

ContactPointState ContactState::point(std::size_t face, std::size_t q) const {
  return {gap_[face * pointsPerFace_ + q], pressure_[face * pointsPerFace_ + q]};
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
  if (snapshot.gap.size() != n || snapshot.pressure.size() != n || n % pointsPerFace_ != 0)
    throw std::invalid_argument("contact state: " + std::to_string(n) + " multipliers, " +
                                std::to_string(snapshot.gap.size()) + " gaps and " +
                                std::to_string(snapshot.pressure.size()) +
                                " pressures; expected equal counts, " + std::to_string(pointsPerFace_) +
                                " per contact face");
  committed_ = trial_ = snapshot.multipliers;
  gap_ = snapshot.gap;
  pressure_ = snapshot.pressure;
}

}  // namespace glossa::contact
