#pragma once
// The pressure of a follower load as a function of the reference position and time
// (doc/theory.md "Loads", paper §7.2, §8.3, §8.5):
//   p(X, t) = p_max s(X) b(t),
// s(X) = 1 (uniform) or the linear profile of §8.3, 0 at P_A and 1 at P_P,
//   s = clamp((X - P_A).(P_P - P_A) / |P_P - P_A|^2, 0, 1),
// constant on planes normal to P_P - P_A and clamped beyond the two points; b(t) any time factor
// (a ramp or table of model::TimeFunction, or the breathing profile of eq. 27 below).
// p is a function of the REFERENCE position X: FollowerPressure holds it fixed while the face
// deforms (doc/loads.md). Sign as FollowerPressure: p > 0 compresses, p < 0 is suction (the
// airway pressure of §8.3 is p_max = -500 Pa at P_P). Eigen only.

#include <Eigen/Core>
#include <array>
#include <functional>

#include "loads/DeadTraction.hpp"

namespace glossa::loads {

// The breathing profile of eq. 27, b(t) = sin(omega (t - start))^exponent with omega = 2 pi /
// period (the paper: exponent 1.75, omega = 2 pi / 2.5 s), made real and non-negative:
//  - HalfWave (the default): b = max(sin, 0)^exponent, one pressure hump per 2.5 s breath (the
//    negative airway pressure of inspiration) and no load during the other half period;
//  - FullWave: b = |sin|^exponent, a hump every half period (1.25 s).
// b = 0 before `start`. The choice and its reasons: doc/loads.md.
struct BreathingProfile {
  enum class Rectification { HalfWave, FullWave };

  double period = 2.5;     // [s], > 0
  double exponent = 1.75;  // > 0
  double start = 0.0;      // [s]
  Rectification rectification = Rectification::HalfWave;

  // Throws std::invalid_argument unless period and exponent are finite and > 0 and start finite.
  void validate() const;
  double operator()(double t) const;
};

class PressureField {
 public:
  using TimeFactor = std::function<double(double)>;

  // s(X) = 1.
  static PressureField uniform(double pMax, TimeFactor b = constantTimeFactor());
  // s(X) linear from 0 at PA to 1 at PP; throws std::invalid_argument if PA == PP.
  static PressureField linear(double pMax, const Eigen::Vector3d &PA, const Eigen::Vector3d &PP,
                              TimeFactor b = constantTimeFactor());
  static TimeFactor constantTimeFactor() {
    return [](double) { return 1.0; };
  }

  double pMax() const { return pMax_; }
  // s(X) in [0, 1].
  double spatialFactor(const Eigen::Vector3d &X) const;
  double timeFactor(double t) const { return b_(t); }
  // p(X, t) = p_max s(X) b(t) [Pa].
  double operator()(const Eigen::Vector3d &X, double t) const { return pMax_ * spatialFactor(X) * b_(t); }
  // p at the four reference Gauss points of a face, in the order followerPressureForces takes.
  std::array<double, 4> atGaussPoints(const FaceNodes &X, double t) const;

 private:
  PressureField(double pMax, bool linear, const Eigen::Vector3d &PA, const Eigen::Vector3d &PP, TimeFactor b);

  double pMax_;
  bool linear_;
  Eigen::Vector3d PA_, dirOverLength2_;  // (P_P - P_A) / |P_P - P_A|^2
  TimeFactor b_;
};

}  // namespace glossa::loads
