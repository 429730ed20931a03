#pragma once
// A dead (reference-configuration) traction on a bilinear quadrilateral face: the nodal forces
// f_a = int_A N_a t dA, as deal.II step-44 applies its pressure patch. Eigen only.

#include <Eigen/Core>

namespace glossa::loads {

using FaceNodes = Eigen::Matrix<double, 4, 3>; // reference coordinates, one row per face node
using FaceForces = Eigen::Matrix<double, 12, 1>;

// 2x2 Gauss rule; t is a force per reference area [Pa].
FaceForces deadTractionForces(const FaceNodes &X, const Eigen::Vector3d &t);

// Reference area of the face (same rule).
double faceArea(const FaceNodes &X);

// 1/3 of the integral of x . n over the face (x its nodes' positions, n the normal of the
// right-hand node order); exact for a bilinear face (the integrand is of degree 3 in s and t).
// Summed over a closed surface with outward normals: the enclosed volume (divergence theorem).
double faceVolumeMoment(const FaceNodes &x);

// Outward unit normal at the face centre for the right-hand node order.
Eigen::Vector3d faceNormal(const FaceNodes &X);

} // namespace glossa::loads
