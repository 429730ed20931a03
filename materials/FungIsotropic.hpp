#pragma once
// Isochoric Fung-type law psi = A (exp(B (I1-bar - 3)) - 1): adipose tissue (paper eq. 9,
// A1 = 2500 Pa, B1 = 2.75) and the muscle matrix (eq. 10, c = 1.652 kPa, b = 0.6265; the form of
// Martins et al. 1998). Prefactor convention and its consequences: doc/materials.md.
// Small-strain shear modulus mu = 2 A B (psi -> A B (I1-bar - 3) = mu/2 (I1-bar - 3)).

#include "materials/IsochoricMaterial.hpp"

namespace glossa::materials {

class FungIsotropic final : public IsochoricMaterial {
 public:
  // A [Pa] > 0, B [-] > 0.
  FungIsotropic(double A, double B);
  static FungIsotropic adipose();       // eq. 9: A1 = 2500 Pa, B1 = 2.75
  static FungIsotropic muscleMatrix();  // eq. 10, Table I: c = 1.652 kPa, b = 0.6265

  PointResponse evaluate(const Eigen::Matrix3d &F) const override;
  double shearModulus() const override { return 2.0 * A_ * B_; }
  double A() const { return A_; }
  double B() const { return B_; }

 private:
  double A_;
  double B_;
};

}  // namespace glossa::materials
