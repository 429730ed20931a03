#pragma once
// The isochoric (deviatoric) part of a hyperelastic point law, in the form the Q1-P0 element
// needs (doc/theory.md, eq. 2): the element adds the volumetric part itself from the
// element-constant pressure, so a material writes only psi_iso(F) = psi(C-bar).
// Pure and const: one call returns energy, first Piola stress and its derivative.

#include <Eigen/Core>
#include <Eigen/LU>

namespace glossa::materials {

// dP/dF stored as a 9x9 matrix: row i*3+J, column k*3+L holds dP_iJ / dF_kL.
using Tangent9 = Eigen::Matrix<double, 9, 9>;

struct PointResponse {
  double energy = 0.0;                             // psi_iso [J/m^3]
  Eigen::Matrix3d P = Eigen::Matrix3d::Zero();     // first Piola-Kirchhoff stress [Pa]
  Tangent9 dPdF = Tangent9::Zero();                // consistent tangent [Pa]
};

class IsochoricMaterial {
public:
  virtual ~IsochoricMaterial() = default;
  // Requires det F > 0 (the element checks before calling).
  virtual PointResponse evaluate(const Eigen::Matrix3d &F) const = 0;
  // Small-strain shear modulus: scales the augmented-Lagrangian penalty and Dirichlet rows.
  virtual double shearModulus() const = 0;
};

} // namespace glossa::materials
