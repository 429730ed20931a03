#pragma once
// The state of one contact (a face set against an obstacle) on one rank, per contact face and
// contact point: the augmented-Lagrangian multiplier lambda_q and, with friction or tied contact,
// the anchor (contact/FrictionLaw, in the obstacle's own frame) and the accumulated slip, each
// committed and trial; and what the last evaluation found (gap, pressure, tangential traction,
// tied), for the Uzawa update, the gap tolerance and the output.
//
// As the muscle history: a step starts with trial = committed; the Uzawa loop updates the trial
// multipliers from the gaps recorded at each converged Newton solve, and each record writes the
// trial anchors and slips of that solve; a converged step commits, a failed one rolls back. A plain
// value type (flat vectors of doubles, pointsPerFace per face: 4 for a rigid obstacle, n x n for a
// deformable pair's slave faces), so that the run can checkpoint it. Eigen only.

#include <cstddef>
#include <vector>

#include "contact/FaceContact.hpp"

namespace glossa::contact {

class ContactState {
public:
  static constexpr std::size_t kPointsPerFace = 4; // a rigid obstacle's faces

  ContactState() = default;
  explicit ContactState(std::size_t faces, std::size_t pointsPerFace = kPointsPerFace);

  std::size_t pointsPerFace() const { return pointsPerFace_; }
  std::size_t faces() const { return committed_.size() / pointsPerFace_; }
  // A face's four multipliers (pointsPerFace 4).
  FaceMultipliers committedMultipliers(std::size_t face) const { return get(committed_, face); }
  // What the Newton solves of the current step evaluate the face with.
  FaceMultipliers trialMultipliers(std::size_t face) const { return get(trial_, face); }
  double trialMultiplier(std::size_t face, std::size_t q) const { return trial_[face * pointsPerFace_ + q]; }
  // The anchors the step's return mapping starts from (NaN: none; pointsPerFace 4).
  FaceAnchors committedAnchors(std::size_t face) const;

  // The gaps, pressures and friction state of a face (pointsPerFace 4), or of one point, at the
  // last evaluation; its anchors and slips become the trial ones.
  void record(std::size_t face, const FaceContactPoints &points);
  void record(std::size_t face, std::size_t q, const ContactPointState &point);
  // As recorded; `slip` the accumulated trial slip, `anchor` the trial anchor.
  ContactPointState point(std::size_t face, std::size_t q) const;

  // The Uzawa update at the recorded gaps: trial lambda_q <- max(0, trial lambda_q - eps g_q).
  void updateMultipliers(double penalty);
  // The largest gapError over the recorded points [m]: what the outer loop's gap tolerance tests.
  double largestGapError() const;
  // The largest penetration -g over the recorded active points [m] (0 if none), for the output.
  double largestPenetration() const;

  void commit();
  void rollBack();

  // The committed multipliers, anchors (3 per point, NaN for none) and accumulated slips, and the
  // recorded gaps and pressures, for a checkpoint, and their restoration (trial = committed, as
  // after commit). restore refuses sizes that do not match: pointsPerFace points per face, 3
  // anchor coordinates per point.
  struct Snapshot {
    std::vector<double> multipliers, gap, pressure, anchors, slip;
  };
  Snapshot snapshot() const { return {committed_, gap_, pressure_, committedAnchor_, committedSlip_}; }
  void restore(const Snapshot &snapshot);

private:
  FaceMultipliers get(const std::vector<double> &values, std::size_t face) const;

  std::size_t pointsPerFace_ = kPointsPerFace;
  std::vector<double> committed_, trial_, gap_, pressure_;
  std::vector<double> committedAnchor_, trialAnchor_, committedSlip_, trialSlip_, tangential_;
  std::vector<char> tied_;
};

}  // namespace glossa::contact
