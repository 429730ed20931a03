#include "materials/MooneyRivlin.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "materials/IsochoricInvariant.hpp"

namespace glossa::materials {

MooneyRivlin::MooneyRivlin(const MooneyRivlinParameters &c) : c_(c) {
  for (const auto &[name, value] :
       {std::pair{"C10", c.C10}, {"C01", c.C01}, {"C11", c.C11}, {"C20", c.C20}, {"C02", c.C02}})
    if (!std::isfinite(value)) throw std::invalid_argument(std::string("MooneyRivlin: ") + name + " must be finite");
  if (!(c.C10 + c.C01 > 0.0))
    throw std::invalid_argument("MooneyRivlin: C10 + C01 must be > 0 (the small-strain shear modulus is 2 (C10 + C01))");
}

MooneyRivlin MooneyRivlin::artisynthTongue() {
  MooneyRivlinParameters c;
  c.C10 = 1037.0;
  c.C20 = 486.0;
  return MooneyRivlin(c);
}

PointResponse MooneyRivlin::evaluate(const Eigen::Matrix3d &F) const {
  const IsochoricInvariant I1 = isochoricI1(F);
  const IsochoricInvariant I2 = isochoricI2(F);
  const double a = I1.value - 3.0, b = I2.value - 3.0;
  // psi(a, b) and its partial derivatives.
  const double W1 = c_.C10 + c_.C11 * b + 2.0 * c_.C20 * a;
  const double W2 = c_.C01 + c_.C11 * a + 2.0 * c_.C02 * b;
  const double W11 = 2.0 * c_.C20, W22 = 2.0 * c_.C02, W12 = c_.C11;

  PointResponse r;
  r.energy = c_.C10 * a + c_.C01 * b + c_.C11 * a * b + c_.C20 * a * a + c_.C02 * b * b;
  r.P = W1 * I1.dF + W2 * I2.dF;
  const Vector9 g1 = flatten(I1.dF), g2 = flatten(I2.dF);
  r.dPdF = W11 * g1 * g1.transpose() + W22 * g2 * g2.transpose() + W12 * (g1 * g2.transpose() + g2 * g1.transpose()) +
           W1 * I1.d2F + W2 * I2.d2F;
  return r;
}

} // namespace glossa::materials
