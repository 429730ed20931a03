#pragma once
// The parallel element of the Hill three-element fibre (paper eq. 14 and 17; Martins et al.
// 1998): T_p = T0max f_p(lambda), f_p = 2 a A (lambda - 1) exp(a (lambda - 1)^2) for lambda > 1,
// else 0 (tension only). f_p is exactly d/dlambda of A (exp(a (lambda - 1)^2) - 1), so the
// element has the energy psi_p = T0max A (exp(a (lambda - 1)^2) - 1) for lambda > 1.
// Table I: a = 12.43 (exponent coefficient), A = 8.568e-4 (fraction of T0max), T0max = 668.8 kPa;
// the order of a and A in the extracted table is resolved in doc/materials.md.
// Also the passive fibre law of FibreReinforcedMaterial.

#include "materials/FibreLaw.hpp"

namespace glossa::materials {

class ParallelElement final : public FibreLaw {
 public:
  static constexpr double kTableIT0max = 668.8e3;  // Pa
  static constexpr double kTableIa = 12.43;
  static constexpr double kTableIA = 8.568e-4;

  ParallelElement(double T0max, double a, double A);  // all > 0
  static ParallelElement tableI() { return {kTableIT0max, kTableIa, kTableIA}; }

  FibreTension evaluate(double lambda) const override;
  // Axial stiffness at lambda = 1+ : T0max 2 a A (14.2 kPa for Table I).
  double initialStiffness() const { return 2.0 * T0max_ * a_ * A_; }
  double T0max() const { return T0max_; }

 private:
  double T0max_;
  double a_;
  double A_;
};

}  // namespace glossa::materials
