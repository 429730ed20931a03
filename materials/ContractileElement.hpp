#pragma once
// The contractile element of the Hill three-element fibre (paper eq. 16):
//   T_c = T0s T0max f_cL(lambda_c) f_cV(d lambda_c/dt) alpha,
// T0max the peak isometric stress (Table I: 668.8 kPa), T0s in [0, 1] the scaling of §6
// (FFMR = T0s alpha), alpha in [0, 1] the activation (eq. 24).

#include "materials/ContractileCurveSets.hpp"

namespace glossa::materials {

struct ContractileTension {
  double T = 0.0;         // T_c [Pa]
  double dLambdaC = 0.0;  // partial dT_c / d lambda_c at fixed rate
  double dRate = 0.0;     // partial dT_c / d (d lambda_c/dt)
};

class ContractileElement {
 public:
  // T0max > 0, T0s in [0, 1], both curves non-null.
  ContractileElement(double T0max, double T0s, ContractileCurves curves);

  ContractileTension evaluate(double lambdaC, double rate, double alpha) const;
  // sup over lambda_c and rate of T_c / (T0max alpha) (bounds the local solve).
  double capacityBound() const;
  // The fastest shortening the element can sustain with non-zero force: f_cV = 0 below -vmax.
  double maxShorteningRate() const;

  double T0max() const { return T0max_; }
  double T0s() const { return T0s_; }
  const ContractileCurves &curves() const { return curves_; }

 private:
  double T0max_;
  double T0s_;
  ContractileCurves curves_;
};

}  // namespace glossa::materials
