#include "materials/Yeoh.hpp"

#include <cmath>
#include <stdexcept>

#include "materials/IsochoricInvariant.hpp"

namespace glossa::materials {

Yeoh::Yeoh(double C10, double C20, double C30) : C10_(C10), C20_(C20), C30_(C30) {
  if (!(C10 > 0.0) || !std::isfinite(C10)) throw std::invalid_argument("Yeoh: C10 must be > 0");
  if (!std::isfinite(C20)) throw std::invalid_argument("Yeoh: C20 must be finite");
  if (!std::isfinite(C30)) throw std::invalid_argument("Yeoh: C30 must be finite");
}

PointResponse Yeoh::evaluate(const Eigen::Matrix3d &F) const {
  const IsochoricInvariant I1 = isochoricI1(F);
  const double a = I1.value - 3.0;
  const double dPsi = C10_ + 2.0 * C20_ * a + 3.0 * C30_ * a * a; // d psi / d I1b
  const double d2Psi = 2.0 * C20_ + 6.0 * C30_ * a;
  PointResponse r;
  r.energy = a * (C10_ + a * (C20_ + a * C30_));
  r.P = dPsi * I1.dF;
  const Vector9 g = flatten(I1.dF);
  r.dPdF = d2Psi * g * g.transpose() + dPsi * I1.d2F;
  return r;
}

} // namespace glossa::materials
