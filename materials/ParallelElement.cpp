#include "materials/ParallelElement.hpp"

#include <cmath>
#include <stdexcept>

namespace glossa::materials {

ParallelElement::ParallelElement(double T0max, double a, double A) : T0max_(T0max), a_(a), A_(A) {
  if (!(T0max > 0.0 && a > 0.0 && A > 0.0) || !std::isfinite(T0max * a * A))
    throw std::invalid_argument("ParallelElement: T0max, a and A must be finite and > 0");
}

FibreTension ParallelElement::evaluate(double lambda) const {
  FibreTension t;
  if (!(lambda > 1.0)) return t;  // eq. 17: no resistance in compression
  const double d = lambda - 1.0;
  const double e = std::exp(a_ * d * d);
  t.energy = T0max_ * A_ * (e - 1.0);
  t.T = T0max_ * 2.0 * a_ * A_ * d * e;
  t.dTdLambda = T0max_ * 2.0 * a_ * A_ * e * (1.0 + 2.0 * a_ * d * d);
  return t;
}

}  // namespace glossa::materials
