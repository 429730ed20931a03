#pragma once
// A follower pressure sigma = -p I on the DEFORMED bilinear quadrilateral face (doc/theory.md
// "Loads", paper §7.2 and §8.3, eq. 27): the external nodal forces
//   f_a = -int p N_a n da = -int_{[-1,1]^2} p N_a (x_,s x x_,t) ds dt,   x = X + u,
// with the 2x2 Gauss rule of DeadTraction (exact for the vector area of a bilinear face), and
// their consistent tangent K = df/du (not symmetric in general). Eigen only.
//
// Conventions (doc/loads.md):
//  - Node order and normal as DeadTraction: the right-hand normal of the node order, (x_2 - x_0)
//    x (x_3 - x_1), points OUT of the body (mesh::kHexFaceNodes). p > 0 pushes against that
//    normal, i.e. compresses the body; p < 0 (airway suction, paper §8.3) pulls it out.
//  - The forces are EXTERNAL forces: add f to f_ext. The residual is f_int - f_ext, so the
//    global tangent gets -K.
//  - p is given at the four Gauss points and is held fixed while u varies: the caller
//    evaluates it at the REFERENCE Gauss point positions (followerPressureGaussPoints(X)), so
//    a spatially varying p(X) does not move with the material and K is the geometric term alone.

#include <Eigen/Core>
#include <array>

#include "loads/DeadTraction.hpp"

namespace glossa::loads {

using FaceTangent = Eigen::Matrix<double, 12, 12>;  // K(3a + i, 3b + j) = d f_{a,i} / d u_{b,j}

// The face-local coordinates (s, t) of the Gauss points, in the order of pAtGaussPoints.
// Node a of the face sits at s = (-1, 1, 1, -1)[a], t = (-1, -1, 1, 1)[a].
const std::array<Eigen::Vector2d, 4> &followerPressureGaussCoordinates();

// The reference positions X(s_q, t_q) of the four Gauss points, where the caller evaluates p.
std::array<Eigen::Vector3d, 4> followerPressureGaussPoints(const FaceNodes &X);

// External nodal forces (one 3-block per face node) of the pressure pAtGaussPoints[q] [Pa] on
// the deformed face x = X + u; if K is not null, also K = df/du.
FaceForces followerPressureForces(const FaceNodes &X, const FaceNodes &u,
                                  const std::array<double, 4> &pAtGaussPoints, FaceTangent *K = nullptr);

// The same with one uniform pressure p on the face.
FaceForces followerPressureForces(const FaceNodes &X, const FaceNodes &u, double p, FaceTangent *K = nullptr);

}  // namespace glossa::loads
