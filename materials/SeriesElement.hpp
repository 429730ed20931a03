#pragma once
// The series element of the Hill three-element fibre (paper eq. 15 and 18; Martins et al. 1998):
// with lambda_s = lambda_f / lambda_c (eq. 13),
//   T_s = T0max c1 (exp(c2 (lambda_s - 1)) - 1) for lambda_s > 1, else 0 (tension only).
// Table I: c1 = 0.1, c2 = 100 (series stiffness c1 c2 T0max = 10 T0max at lambda_s = 1+).
// Its stored energy at fixed lambda_c (d psi_s / d lambda_f = T_s) is
//   psi_s = T0max c1 lambda_c [(exp(c2 (lambda_s - 1)) - 1) / c2 - (lambda_s - 1)].

namespace glossa::materials {

struct SeriesTension {
  double T = 0.0;         // T_s [Pa]
  double dLambdaF = 0.0;  // dT_s / d lambda_f
  double dLambdaC = 0.0;  // dT_s / d lambda_c
  double energy = 0.0;    // psi_s at fixed lambda_c [J/m^3]
};

class SeriesElement {
 public:
  static constexpr double kTableIc1 = 0.1;
  static constexpr double kTableIc2 = 100.0;

  SeriesElement(double T0max, double c1, double c2);  // all > 0
  static SeriesElement tableI(double T0max) { return {T0max, kTableIc1, kTableIc2}; }

  // Requires lambdaF > 0, lambdaC > 0.
  SeriesTension evaluate(double lambdaF, double lambdaC) const;
  // The series stretch at which T_s = tension (>= 0): 1 + ln(1 + tension/(T0max c1)) / c2.
  double stretchAtTension(double tension) const;
  double T0max() const { return T0max_; }

 private:
  double T0max_;
  double c1_;
  double c2_;
};

}  // namespace glossa::materials
