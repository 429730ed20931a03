#include "materials/VolumetricEnergy.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace glossa::materials {

VolumetricEnergy::VolumetricEnergy(Form form, double kappa) : form_(form), kappa_(kappa) {
  if (!(kappa >= 0.0)) throw std::invalid_argument("VolumetricEnergy: kappa must be >= 0");
}

VolumetricEnergy::Form VolumetricEnergy::formFromName(const std::string &name) {
  if (name == "simo-taylor") return Form::SimoTaylor;
  if (name == "log-squared") return Form::LogSquared;
  if (name == "quadratic") return Form::Quadratic;
  throw std::invalid_argument("unknown volumetric energy '" + name + "'");
}

double VolumetricEnergy::energy(double t) const {
  switch (form_) {
  case Form::SimoTaylor: return 0.25 * kappa_ * (t * t - 1.0 - 2.0 * std::log(t));
  case Form::LogSquared: return 0.5 * kappa_ * std::log(t) * std::log(t);
  case Form::Quadratic: return 0.5 * kappa_ * (t - 1.0) * (t - 1.0);
  }
  return 0.0;
}

double VolumetricEnergy::dU(double t) const {
  switch (form_) {
  case Form::SimoTaylor: return 0.5 * kappa_ * (t - 1.0 / t);
  case Form::LogSquared: return kappa_ * std::log(t) / t;
  case Form::Quadratic: return kappa_ * (t - 1.0);
  }
  return 0.0;
}

double VolumetricEnergy::d2U(double t) const {
  switch (form_) {
  case Form::SimoTaylor: return 0.5 * kappa_ * (1.0 + 1.0 / (t * t));
  case Form::LogSquared: return kappa_ * (1.0 - std::log(t)) / (t * t);
  case Form::Quadratic: return kappa_;
  }
  return 0.0;
}

double VolumetricEnergy::dilatationAtPressure(double p) const {
  const double kappa = kappa_;
  if (std::isinf(kappa)) return 1.0;
  const double s = p / kappa;
  switch (form_) {
    case Form::Quadratic:
      return 1.0 + s;
    case Form::SimoTaylor:
      // kappa/2 (theta - 1/theta) = p  <=>  theta^2 - 2 s theta - 1 = 0, positive root.
      return s + std::sqrt(s * s + 1.0);
    case Form::LogSquared: {
      // kappa ln(theta)/theta = p has a root in (0, e] only for s <= 1/e (U' is increasing there
      // and peaks at theta = e); beyond, the law cannot carry the pressure: report e.
      if (s >= 1.0 / std::exp(1.0)) return std::exp(1.0);
      double lo = std::numeric_limits<double>::min(), hi = std::exp(1.0);
      for (int k = 0; k < 200 && hi - lo > 4.0 * std::numeric_limits<double>::epsilon() * hi; ++k) {
        const double mid = 0.5 * (lo + hi);
        (std::log(mid) / mid < s ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
  }
  return 1.0;
}

double bulkModulus(double mu, double nu) {
  if (!(nu > -1.0 && nu < 0.5)) throw std::invalid_argument("Poisson's ratio must be in (-1, 0.5)");
  return 2.0 * mu * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu));
}

} // namespace glossa::materials
