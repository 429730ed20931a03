#include "contact/ContactState.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace glossa::contact {

namespace {
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
}

ContactState::ContactState(std::size_t faces, std::size_t pointsPerFace)
    : pointsPerFace_(pointsPerFace),
      committed_(faces * pointsPerFace, 0.0),
      trial_(faces * pointsPerFace, 0.0),
      // Nothing evaluated yet: no point is known to be near the obstacle.
      gap_(faces * pointsPerFace, std::numeric_limits<double>::infinity()),
      pressure_(faces * pointsPerFace, 0.0),
      committedAnchor_(3 * faces * pointsPerFace, kNone),
      trialAnchor_(3 * faces * pointsPerFace, kNone),
      committedSlip_(faces * pointsPerFace, 0.0),
      trialSlip_(faces * pointsPerFace, 0.0),
      tangential_(faces * pointsPerFace, 0.0),
      tied_(faces * pointsPerFace, 0) {
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

FaceAnchors ContactState::committedAnchors(std::size_t face) const {
  if (pointsPerFace_ != kPointsPerFace)
    throw std::logic_error("contact state: four anchors asked of a face with " + std::to_string(pointsPerFace_) +
                           " points");
  FaceAnchors anchors;
  for (std::size_t q = 0; q < kPointsPerFace; ++q)
    anchors[q] = Eigen::Vector3d(committedAnchor_.data() + 3 * (face * kPointsPerFace + q));
  return anchors;
}

void ContactState::record(std::size_t face, const FaceContactPoints &points) {
  for (std::size_t q = 0; q < kPointsPerFace; ++q) record(face, q, points[q]);
}

void ContactState::record(std::size_t face, std::size_t q, const ContactPointState &point) {
  const std::size_t i = face * pointsPerFace_ + q;
  gap_[i] = point.gap;
  pressure_[i] = point.pressure;
  tangential_[i] = point.tangential;
  tied_[i] = point.tied;
  trialSlip_[i] = committedSlip_[i] + point.slip;
  for (int k = 0; k < 3; ++k) trialAnchor_[3 * i + k] = point.anchor(k);
}

ContactPointState ContactState::point(std::size_t face, std::size_t q) const {
  const std::size_t i = face * pointsPerFace_ + q;
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
  if (snapshot.gap.size() != n || snapshot.pressure.size() != n || n % pointsPerFace_ != 0 ||
      snapshot.anchors.size() != 3 * n || snapshot.slip.size() != n)
    throw std::invalid_argument("contact state: " + std::to_string(n) + " multipliers, " +
                                std::to_string(snapshot.gap.size()) + " gaps, " +
                                std::to_string(snapshot.pressure.size()) + " pressures, " +
                                std::to_string(snapshot.anchors.size()) + " anchor coordinates and " +
                                std::to_string(snapshot.slip.size()) + " slips; expected equal counts, " +
                                std::to_string(pointsPerFace_) + " per contact face, and 3 anchor coordinates each");
  committed_ = trial_ = snapshot.multipliers;
  gap_ = snapshot.gap;
  pressure_ = snapshot.pressure;
  committedAnchor_ = trialAnchor_ = snapshot.anchors;
  committedSlip_ = trialSlip_ = snapshot.slip;
  tangential_.assign(n, 0.0);
  tied_.assign(n, 0);
}

}  // namespace glossa::contact
