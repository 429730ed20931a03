#pragma once
// The contact quantities of a point against one triangle of a surface with a smoothed normal
// field (doc/contact.md, "Smoothed normals"): the closest point p is the faceted surface's, but
// the normal there is interpolated from unit vertex normals (Phong's normals),
//   n = m / |m|,   m = sum_i lambda_i(p) N_i,
// lambda_i the barycentric coordinates of p in the triangle and N_i the angle-weighted vertex
// normals (TriangleSurface's pseudonormals, made unit). On an edge only its two vertices count,
// so n is the same from either triangle: it turns continuously as p crosses from a triangle to
// its neighbour, where the face normals of a coarse surface jump. The gap is (x - p) . n.
//  - dNormal = (I - n n) / |m| sum_i N_i (d lambda_i/dx)^T, with dp/dx = I - f f (f the face
//    normal) on the interior, e e on an edge e, 0 at a corner.
//  - The gap's gradient is no longer n: dg/dx = (I - dp/dx)^T n + dNormal^T (x - p), carried in
//    ClosestPoint::dGap for the contact tangent.
// On the free boundary of an open sheet the faceted answer stands (SurfaceProjection): beside the
// sheet the gap is the distance, apart, whatever the interpolated normal says.

#include <cstddef>

#include "contact/Obstacle.hpp"
#include "contact/TriangleSurface.hpp"

namespace glossa::contact {

ClosestPoint projectOnSmoothedTriangle(const TriangleSurface &surface, std::size_t triangle,
                                       const Eigen::Vector3d &x);

}  // namespace glossa::contact
