#pragma once
// A one-dimensional elastic fibre law psi_f(lambda) (doc/theory.md, eq. 2, 11): energy per unit
// reference volume of the fibre constituent, its derivative, the tension T = psi_f'(lambda)
// (the "one-dimensional tensile force" of eq. 11, a stress in Pa), and dT/dlambda.
// Pure and const.

namespace glossa::materials {

struct FibreTension {
  double energy = 0.0;     // psi_f [J/m^3]
  double T = 0.0;          // d psi_f / d lambda [Pa]
  double dTdLambda = 0.0;  // [Pa]
};

class FibreLaw {
 public:
  virtual ~FibreLaw() = default;
  virtual FibreTension evaluate(double lambda) const = 0;
};

}  // namespace glossa::materials
