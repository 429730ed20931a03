#pragma once
// The state of one contact (a face set against an obstacle) on one rank, per contact face and
// contact point: the augmented-Lagrangian multiplier lambda_q, committed and trial, and the gap
// and pressure of the last evaluation, for the Uzawa update, the gap tolerance and the output.
//
// As the muscle history: a step starts with trial = committed; the Uzawa loop updates the trial
// multipliers from the gaps recorded at each converged Newton solve; a converged step commits, a
// failed one rolls back. A plain value type (flat vectors of doubles, pointsPerFace per face: 4
// for a rigid obstacle, n x n for a deformable pair's slave faces), so that the run can
// checkpoint it. Eigen only.

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

  // The gaps and pressures of a face (pointsPerFace 4), or of one point, at the last evaluation.
  void record(std::size_t face, const FaceContactPoints &points);
  void record(std::size_t face, std::size_t q, const ContactPointState &point);
  ContactPointState point(std::size_t face, std::size_t q) const;

  // The Uzawa update at the recorded gaps: trial lambda_q <- max(0, trial lambda_q - eps g_q).
  void updateMultipliers(double penalty);
  // The largest gapError over the recorded points [m]: what the outer loop's gap tolerance tests.
  double largestGapError() const;
  // The largest penetration -g over the recorded active points [m] (0 if none), for the output.
  double largestPenetration() const;

  void commit() { committed_ = trial_; }
  void rollBack() { trial_ = committed_; }

  // The committed multipliers and the recorded gaps and pressures, for a checkpoint, and their
  // restoration (trial = committed, as after commit). restore refuses vectors of unequal sizes or
  // sizes not a multiple of pointsPerFace.
  struct Snapshot {
    std::vector<double> multipliers, gap, pressure;
  };
  Snapshot snapshot() const { return {committed_, gap_, pressure_}; }
  void restore(const Snapshot &snapshot);

private:
  FaceMultipliers get(const std::vector<double> &values, std::size_t face) const;

  std::size_t pointsPerFace_ = kPointsPerFace;
  std::vector<double> committed_, trial_, gap_, pressure_;
};

}  // namespace glossa::contact
