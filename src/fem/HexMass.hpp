#pragma once
// The mass matrix of a trilinear hexahedron of uniform density rho (doc/dynamics.md):
//   consistent  M_{3a+i, 3b+j} = delta_ij int_V rho N_a N_b dV   (2x2x2 Gauss: N_a N_b is
//               quadratic in each reference coordinate, so the rule is exact for an affine element),
//   lumped      the row sums of the consistent one on the diagonal, m_a = int_V rho N_a dV
//               (positive for a trilinear hexahedron, and the same total mass and momentum).
// Both carry the reference configuration's mass, which the motion conserves, so M is constant
// in a Lagrangian description. Eigen only.

#include <Eigen/Core>

#include "fem/HexShape.hpp"

namespace glossa::fem {

enum class MassLumping { consistent, lumped };

using ElementMass = Eigen::Matrix<double, 24, 24>; // dof 3*a + i

// rho: density [kg/m^3]. A degenerate element (det dX/dxi <= 0 at a quadrature point) gets a
// zero matrix and false.
bool hexMass(const NodeMatrix &X, double rho, MassLumping lumping, ElementMass &M);

} // namespace glossa::fem
