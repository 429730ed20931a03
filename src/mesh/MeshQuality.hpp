#pragma once
// Geometric quality measures of hexahedral meshes: volume and the scaled Jacobian. Used by
// the generators' tests and by mesh import to refuse inverted or badly shaped elements
// before a solve wastes Newton iterations on them.

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "mesh/HexMesh.hpp"

namespace glossa::mesh {

// Volume of one trilinear hex, V = \int_{[-1,1]^3} det(dX/dxi) dxi, by 2x2x2 Gauss. det J of a
// trilinear map is quadratic in each reference coordinate, so this rule is exact.
double elementVolume(const Eigen::Matrix<double, 8, 3> &X);

// Smallest det(dX/dxi) over the eight 2x2x2 Gauss points: the quantity the element kernels
// divide by. Mesh import refuses an element where it is not positive (inverted or degenerate).
double minGaussPointJacobian(const Eigen::Matrix<double, 8, 3> &X);

// Sum of elementVolume over all elements.
double meshVolume(const HexMesh &mesh);

// Scaled Jacobian of one hex as defined by Verdict (Stimpson et al. 2007, hex_scaled_jacobian):
// at each corner, det[e1 e2 e3] / (|e1| |e2| |e3|) of the three edges leaving the corner in
// right-handed order, and the same of the three principal axes at the centre; the minimum of
// these nine values. 1 for a cube or any rectangular box, < 0 for an inverted element, and 0
// (not Verdict's DBL_MAX) when an edge has zero length, so a collapsed element counts as bad.
double scaledJacobian(const Eigen::Matrix<double, 8, 3> &X);

// (min, max) over elements of scaledJacobian. Throws std::runtime_error for a mesh without
// elements, whose range is undefined.
std::pair<double, double> scaledJacobianRange(const HexMesh &mesh);
// Every element's scaled Jacobian, in the mesh's element order.
std::vector<double> scaledJacobians(const HexMesh &mesh);

}  // namespace glossa::mesh
