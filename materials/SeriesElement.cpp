#include "materials/SeriesElement.hpp"

#include <cmath>
#include <stdexcept>

namespace glossa::materials {

SeriesElement::SeriesElement(double T0max, double c1, double c2) : T0max_(T0max), c1_(c1), c2_(c2) {
  if (!(T0max > 0.0 && c1 > 0.0 && c2 > 0.0) || !std::isfinite(T0max * c1 * c2))
    throw std::invalid_argument("SeriesElement: T0max, c1 and c2 must be finite and > 0");
}

SeriesTension SeriesElement::evaluate(double lambdaF, double lambdaC) const {
  SeriesTension t;
  const double lambdaS = lambdaF / lambdaC;
  if (!(lambdaS > 1.0)) return t;  // slack
  const double e = std::exp(c2_ * (lambdaS - 1.0));
  const double dTdLambdaS = T0max_ * c1_ * c2_ * e;
  t.T = T0max_ * c1_ * (e - 1.0);
  t.dLambdaF = dTdLambdaS / lambdaC;
  t.dLambdaC = -dTdLambdaS * lambdaS / lambdaC;
  t.energy = T0max_ * c1_ * lambdaC * ((e - 1.0) / c2_ - (lambdaS - 1.0));
  return t;
}

double SeriesElement::stretchAtTension(double tension) const {
  return 1.0 + std::log1p(tension / (T0max_ * c1_)) / c2_;
}

}  // namespace glossa::materials
