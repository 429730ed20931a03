#pragma once
// A body force per unit reference volume b = rho a (gravity, or any constant acceleration a of
// the body's frame), dead: nodal forces f_a = int_V N_a dV b on a trilinear hexahedron (2x2x2
// Gauss, exact for the trilinear Jacobian of a parallelepiped and within the rule's error
// otherwise). Quasi-static: the weight is carried by the reference configuration's mass, which
// the deformation conserves. Eigen only.

#include <string>

#include <Eigen/Core>

namespace glossa::loads {

using HexNodes = Eigen::Matrix<double, 8, 3>;     // reference coordinates, VTK order
using HexForces = Eigen::Matrix<double, 24, 1>;   // dof 3*a + i

// b: force per reference volume [N/m^3]. Returns zero forces for a degenerate element.
HexForces bodyForces(const HexNodes &X, const Eigen::Vector3d &b);

// The gravity vector [m/s^2] of a named posture in Glossa's body frame (doc/loads.md): x points
// anterior, y superior, z to the subject's left. Upright: gravity along -y; supine (lying on
// the back): along -x (towards the posterior). Throws std::invalid_argument for another name.
Eigen::Vector3d postureGravity(const std::string &posture, double g);

} // namespace glossa::loads
