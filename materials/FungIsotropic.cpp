#include "materials/FungIsotropic.hpp"

#include <cmath>
#include <stdexcept>

#include "materials/IsochoricInvariant.hpp"

namespace glossa::materials {

FungIsotropic::FungIsotropic(double A, double B) : A_(A), B_(B) {
  if (!(A > 0.0) || !std::isfinite(A)) throw std::invalid_argument("FungIsotropic: A must be > 0");
  if (!(B > 0.0) || !std::isfinite(B)) throw std::invalid_argument("FungIsotropic: B must be > 0");
}

FungIsotropic FungIsotropic::adipose() { return {2500.0, 2.75}; }
FungIsotropic FungIsotropic::muscleMatrix() { return {1652.0, 0.6265}; }

PointResponse FungIsotropic::evaluate(const Eigen::Matrix3d &F) const {
  const IsochoricInvariant I1 = isochoricI1(F);
  const double e = std::exp(B_ * (I1.value - 3.0));
  const double dPsi = A_ * B_ * e;        // d psi / d I1-bar
  const double d2Psi = A_ * B_ * B_ * e;  // d2 psi / d I1-bar^2

  PointResponse r;
  r.energy = A_ * (e - 1.0);
  r.P = dPsi * I1.dF;
  const Vector9 g = flatten(I1.dF);
  r.dPdF = d2Psi * g * g.transpose() + dPsi * I1.d2F;
  return r;
}

}  // namespace glossa::materials
