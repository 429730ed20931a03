#pragma once
// Trilinear shape functions of the 8-node hexahedron and the 2x2x2 Gauss rule, in the VTK node
// order of mesh/HexMesh.hpp.

#include <array>

#include <Eigen/Core>
#include <Eigen/LU>

namespace glossa::fem {

using NodeMatrix = Eigen::Matrix<double, 8, 3>; // one row per node

struct QuadraturePoint {
  Eigen::Vector3d xi;
  double weight;
};

// 2x2x2 Gauss-Legendre points on [-1, 1]^3 (exact for the trilinear mass and Q1 stiffness of
// an affine element).
const std::array<QuadraturePoint, 8> &gaussHex2();

// N_a(xi), a = 0..7.
Eigen::Matrix<double, 8, 1> hexShape(const Eigen::Vector3d &xi);
// dN_a/dxi_j as an 8x3 matrix.
Eigen::Matrix<double, 8, 3> hexShapeGradient(const Eigen::Vector3d &xi);

// Reference coordinates of node a.
Eigen::Vector3d hexNodeXi(int a);

// Spatial gradients at one point of an element with nodal coordinates X:
// dN/dX (8x3) and det(dX/dxi). Returns false if det <= 0.
bool hexGradients(const NodeMatrix &X, const Eigen::Vector3d &xi,
                  Eigen::Matrix<double, 8, 3> &dNdX, double &detJ);

// The smallest det F = det(dx/dxi) / det(dX/dxi) at the eight corners of the element, x = X + u:
// the check the Gauss points cannot make. An element folded through itself can keep J > 0 at
// all eight Gauss points while a corner has turned over (a node pushed past the opposite face).
// A corner whose reference det dX/dxi is exactly 0 has no det F and is left out (+infinity if
// every corner is); a negative one (a turned-over corner of a zero-strain configuration) gives
// the ratio, negative where the deformation has turned that corner back.
double minCornerJacobian(const NodeMatrix &X, const NodeMatrix &u);
// The same over the element's regular corners only: those whose reference det dX/dxi is at least
// `regularity` times the mean of its eight (a poorly shaped hexahedron's near-degenerate corner
// amplifies any motion into a large det F there; a regular corner turned over means the element
// is folded through itself). +infinity if no corner is regular.
double minRegularCornerJacobian(const NodeMatrix &X, const NodeMatrix &u, double regularity);
// Both in one pass over the corners (the Assembler's check after each converged step).
struct CornerJacobians {
  double all, regular;
};
CornerJacobians cornerJacobians(const NodeMatrix &X, const NodeMatrix &u, double regularity);

} // namespace glossa::fem
