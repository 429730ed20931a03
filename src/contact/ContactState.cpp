#include "contact/ContactState.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace glossa::contact {

namespace {
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
}

ContactState::ContactState(std::size_t faces)
    : committed_(faces * kPointsPerFace, 0.0),
      trial_(faces * kPointsPerFace, 0.0),
      // Nothing evaluated yet: no point is known to be near the obstacle.
      gap_(faces * kPointsPerFace, std::numeric_limits<double>::infinity()),
      pressure_(faces * kPointsPerFace, 0.0),
      committedAnchor_(3 * faces * kPointsPerFace, kNone),
      trialAnchor_(3 * faces * kPointsPerFace, kNone),
      committedSlip_(faces * kPointsPerFace, 0.0),
      trialSlip_(faces * kPointsPerFace, 0.0),
      tangential_(faces * kPointsPerFace, 0.0),
      tied_(faces * kPointsPerFace, 0) {}

FaceMultipliers ContactState::get(const std::vector<double> &values, std::size_t face) const {
  FaceMultipliers lambda;
  std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(face * kPointsPerFace), kPointsPerFace, lambda.begin());
  return lambda;
}

FaceAnchors ContactState::committedAnchors(std::size_t face) const {
  FaceAnchors anchors;
  for (std::size_t q = 0; q < kPointsPerFace; ++q)
    anchors[q] = Eigen::Vector3d(committedAnchor_.data() + 3 * (face * kPointsPerFace + q));
  return anchors;
}

void ContactState::record(std::size_t face, const FaceContactPoints &points) {
  for (std::size_t q = 0; q < kPointsPerFace; ++q) {
    const std::size_t i = face * kPointsPerFace + q;
    gap_[i] = points[q].gap;
    pressure_[i] = points[q].pressure;
    tangential_[i] = points[q].tangential;
    tied_[i] = points[q].tied;
    trialSlip_[i] = committedSlip_[i] + points[q].slip;
    for (int k = 0; k < 3; ++k) trialAnchor_[3 * i + k] = points[q].anchor(k);
  }
}

ContactPointState ContactState::point(std::size_t face, std::size_t q) const {
  const std::size_t i = face * kPointsPerFace + q;
  ContactPointState p;
  p.gap = gap_[i];
  p.pressure = pressure_[i];
  p.tangential = tangential_[i];
  p.slip = trialSlip_[i];
  p.tied = tied_[i] != 0;
  p.anchor = Eigen::Vector3d(trialAnchor_.data() + 3 * i);
  return p;
}

void ContactState::updateMultipliers(double penalty) {
  for (std::size_t i = 0; i < trial_.size(); ++i) trial_[i] = updatedMultiplier(trial_[i], penalty, gap_[i]);
}

double ContactState::largestGapError() const {
  double largest = 0.0;
  for (std::size_t i = 0; i < gap_.size(); ++i) {
    ContactPointState p;
    p.gap = gap_[i];
    p.pressure = pressure_[i];
    p.tied = tied_[i] != 0;
    largest = std::max(largest, gapError(p));
  }
  return largest;
}

double ContactState::largestPenetration() const {
  double largest = 0.0;
  for (std::size_t i = 0; i < gap_.size(); ++i)
    if (pressure_[i] > 0 || tied_[i]) largest = std::max(largest, -gap_[i]);
  return largest;
}

void ContactState::commit() {
  committed_ = trial_;
  committedAnchor_ = trialAnchor_;
  committedSlip_ = trialSlip_;
}

void ContactState::rollBack() {
  trial_ = committed_;
  trialAnchor_ = committedAnchor_;
  trialSlip_ = committedSlip_;
}

void ContactState::restore(const Snapshot &snapshot) {
  const std::size_t n = snapshot.multipliers.size();
  if (snapshot.gap.size() != n || snapshot.pressure.size() != n || n % kPointsPerFace != 0 ||
      snapshot.anchors.size() != 3 * n || snapshot.slip.size() != n)
    throw std::invalid_argument("contact state: " + std::to_string(n) + " multipliers, " +
                                std::to_string(snapshot.gap.size()) + " gaps, " +
                                std::to_string(snapshot.pressure.size()) + " pressures, " +
                                std::to_string(snapshot.anchors.size()) + " anchor coordinates and " +
                                std::to_string(snapshot.slip.size()) +
                                " slips; expected equal counts, 4 per contact face, and 3 anchor coordinates each");
  committed_ = trial_ = snapshot.multipliers;
  gap_ = snapshot.gap;
  pressure_ = snapshot.pressure;
  committedAnchor_ = trialAnchor_ = snapshot.anchors;
  committedSlip_ = trialSlip_ = snapshot.slip;
  tangential_.assign(n, 0.0);
  tied_.assign(n, 0);
}

}  // namespace glossa::contact
