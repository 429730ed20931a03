#pragma once
// A triangulated surface made smooth as the zero level set of an implicit moving-least-squares
// function of its vertices and unit vertex normals (Shen, O'Brien and Shewchuk, SIGGRAPH 2004;
// Kolluri, ACM TALG 2008), the third `normal field` of a surface obstacle (doc/contact.md,
// "Implicit surface"):
//   f(x) = sum_i w_i(x) N_i . (x - v_i) / sum_i w_i(x),
//   w_i = phi(|x - v_i| / R),  phi(s) = (1 - s)^4 (4 s + 1) for s < 1, 0 beyond (Wendland's C2),
// over the vertices v_i within the support radius R. The gap is f, the normal n = grad f / |grad f|.
// Why: on the faceted surface, or with normals interpolated on it (SmoothedProjection), the
// gap's gradient is the face normal near the surface and turns by the dihedral angle where a
// contact point's foot crosses an edge: the contact stiffness jumps there, and Newton can
// alternate between the two sides (doc/airway.md). f is C2 wherever the weights do not all
// vanish, so the contact force and its tangent are continuous.
//  - On a flat patch f is the exact signed distance; on a surface of radius of curvature rho it
//    lies inside the vertices by about <r^2> / (2 rho), <r^2> the weighted mean squared distance
//    to the vertices in the support (about 0.1 R^2): a smoothing of the surface, not of the law.
//  - dGap = grad f; dNormal = (I - n n) H / |grad f|, H the Hessian of f.
// Eigen only: the neighbour search is the caller's (TriangulatedObstacle's k-d tree).

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "contact/Obstacle.hpp"
#include "contact/TriangleSurface.hpp"

namespace glossa::contact {

// The support radius by default: this many mean edge lengths of the surface.
constexpr double kImplicitRadiusInEdges = 2.5;
double meanEdgeLength(const TriangleSurface &surface);

// The unit vertex normals N_i: the surface's angle-weighted pseudonormals, made unit once.
std::vector<Eigen::Vector3d> unitVertexNormals(const TriangleSurface &surface);

// f, its gradient and Hessian at x from the vertices `neighbours` (indices into `vertices` and
// `unitNormals`, those within R of x); nothing where their weights sum to less than
// kSmallestWeightSum (x near the edge of every vertex's support: too far from the surface for a
// level set to be defined, or beyond an open sheet).
constexpr double kSmallestWeightSum = 1e-3;
std::optional<ClosestPoint> implicitSurfaceAt(const std::vector<Eigen::Vector3d> &vertices,
                                              const std::vector<Eigen::Vector3d> &unitNormals,
                                              const std::vector<int> &neighbours, const Eigen::Vector3d &x,
                                              double radius);

}  // namespace glossa::contact
