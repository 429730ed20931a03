#pragma once
// The bilinear shape functions of a quadrilateral face and the cross-product matrix the face
// kernels' tangents are written with. Node a sits at s = (-1, 1, 1, -1)[a], t = (-1, -1, 1, 1)[a],
// the node order of DeadTraction (right-hand normal out of the body). Eigen only.

#include <Eigen/Core>

namespace glossa::loads {

struct FaceShape {
  Eigen::Vector4d N, dNds, dNdt;  // N_a(s, t) and its derivatives
};

FaceShape faceShape(double s, double t);

// [v]_x, so that [v]_x w = v x w. With x_,s x x_,t the area vector of a face, its derivative in
// node b's position is dN_b/dt [x_,s]_x - dN_b/ds [x_,t]_x.
Eigen::Matrix3d crossMatrix(const Eigen::Vector3d &v);

}  // namespace glossa::loads
