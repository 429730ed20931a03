#include "materials/ContractileElement.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace glossa::materials {

ContractileElement::ContractileElement(double T0max, double T0s, ContractileCurves curves)
    : T0max_(T0max), T0s_(T0s), curves_(std::move(curves)) {
  if (!(T0max > 0.0) || !std::isfinite(T0max))
    throw std::invalid_argument("ContractileElement: T0max must be > 0");
  if (!(T0s >= 0.0 && T0s <= 1.0)) throw std::invalid_argument("ContractileElement: T0s must be in [0, 1]");
  if (!curves_.forceLength || !curves_.forceVelocity)
    throw std::invalid_argument("ContractileElement: force-length and force-velocity curves are required");
}

ContractileTension ContractileElement::evaluate(double lambdaC, double rate, double alpha) const {
  ContractileTension t;
  const double scale = T0s_ * T0max_ * alpha;
  if (scale == 0.0) return t;
  const CurveValue fL = curves_.forceLength->evaluate(lambdaC);
  const CurveValue fV = curves_.forceVelocity->evaluate(rate);
  t.T = scale * fL.value * fV.value;
  t.dLambdaC = scale * fL.slope * fV.value;
  t.dRate = scale * fL.value * fV.slope;
  return t;
}

double ContractileElement::capacityBound() const {
  return T0s_ * curves_.forceLength->upperBound() * curves_.forceVelocity->upperBound();
}

double ContractileElement::maxShorteningRate() const { return -curves_.forceVelocity->zeroBelow(); }

}  // namespace glossa::materials
