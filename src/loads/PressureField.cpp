#include "loads/PressureField.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "loads/FollowerPressure.hpp"

namespace glossa::loads {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

void BreathingProfile::validate() const {
  if (!(std::isfinite(period) && period > 0.0))
    throw std::invalid_argument("breathing profile: 'period' must be finite and > 0");
  if (!(std::isfinite(exponent) && exponent > 0.0))
    throw std::invalid_argument("breathing profile: 'exponent' must be finite and > 0");
  if (!std::isfinite(start)) throw std::invalid_argument("breathing profile: 'start' must be finite");
}

double BreathingProfile::operator()(double t) const {
  if (t < start) return 0.0;
  const double omega = 2.0 * kPi / period;  // eq. 27: omega = 2 pi / 2.5
  const double s = std::sin(omega * (t - start));
  // sin^1.75 is not real where sin < 0 (eq. 27 as printed): rectify first (doc/loads.md).
  const double r = rectification == Rectification::HalfWave ? std::max(s, 0.0) : std::abs(s);
  return std::pow(r, exponent);
}

PressureField::PressureField(double pMax, bool linear, const Eigen::Vector3d &PA, const Eigen::Vector3d &PP,
                             TimeFactor b)
    : pMax_(pMax), linear_(linear), PA_(PA), dirOverLength2_(Eigen::Vector3d::Zero()), b_(std::move(b)) {
  if (!std::isfinite(pMax)) throw std::invalid_argument("pressure field: p_max must be finite");
  if (!b_) throw std::invalid_argument("pressure field: empty time factor");
  if (linear_) {
    const Eigen::Vector3d d = PP - PA;
    const double length2 = d.squaredNorm();
    if (!(length2 > 0.0) || !std::isfinite(length2))
      throw std::invalid_argument("pressure field: the linear profile needs P_A != P_P (finite)");
    dirOverLength2_ = d / length2;
  }
}

PressureField PressureField::uniform(double pMax, TimeFactor b) {
  return PressureField(pMax, false, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), std::move(b));
}

PressureField PressureField::linear(double pMax, const Eigen::Vector3d &PA, const Eigen::Vector3d &PP,
                                    TimeFactor b) {
  return PressureField(pMax, true, PA, PP, std::move(b));
}

double PressureField::spatialFactor(const Eigen::Vector3d &X) const {
  if (!linear_) return 1.0;
  // §8.3: linear from the tip P_A (0) to the rear P_P (1), constant in the transverse plane.
  return std::clamp((X - PA_).dot(dirOverLength2_), 0.0, 1.0);
}

std::array<double, 4> PressureField::atGaussPoints(const FaceNodes &X, double t) const {
  const double scale = pMax_ * b_(t);
  const std::array<Eigen::Vector3d, 4> points = followerPressureGaussPoints(X);
  std::array<double, 4> p;
  for (std::size_t q = 0; q < 4; ++q) p[q] = scale * spatialFactor(points[q]);
  return p;
}

}  // namespace glossa::loads
