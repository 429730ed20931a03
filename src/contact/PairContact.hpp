#pragma once
// Frictionless contact between two deformable bilinear faces, one pass, segment to segment
// (doc/contact.md, "Deformable pairs and self-contact"): contact points on the SLAVE face (an
// n x n Gauss rule), each projected onto the closest point of a MASTER face in the current
// configuration (a Newton solve for the master's (s, t)), with
//   g = (x_s - x_m(s, t)) . n_m,   n_m = (x_m,s x x_m,t) / |x_m,s x x_m,t|  (out of the master),
//   t = max(0, lambda - eps g)     [Pa],
// the slave point pushed along +n_m and the master face pulled back by the same force, shared
// out by its shape functions at the projection:
//   f_a(slave)  =  w t j_s N_a(q) n_m,        f_b(master) = -w t j_s N_b(s, t) n_m,
// with w the point's weight and j_s the slave face's CURRENT area element (t is a Cauchy traction,
// as for rigid obstacles: loads::FollowerPressure's convention). The master's forces are minus
// the slave's: a pair conserves momentum point by point.
// With K: the consistent tangent d f / d u over the eight nodes (slave 0-3, master 4-7),
// including the variation of the projection (s, t), of the master normal and of the slave area
// element; the active set's kink as FaceContact (trial = 0 counts as touching). Eigen only.

#include <optional>
#include <vector>

#include "contact/FaceContact.hpp"

namespace glossa::contact {

using PairForces = Eigen::Matrix<double, 24, 1>;    // slave nodes 0-3, then master nodes 0-3
using PairTangent = Eigen::Matrix<double, 24, 24>;  // K(3a + i, 3b + j) = d f_{a,i} / d u_{b,j}

// A point of the slave face: its face-local (s, t) and quadrature weight.
struct SlavePoint {
  Eigen::Vector2d st;
  double weight = 1;
};

// The n x n Gauss-Legendre points of a face (n >= 1), weights summing to 4 (the area of
// [-1, 1]^2), ordered s fastest. n = 2 is FaceContact's Gauss rule.
std::vector<SlavePoint> slavePoints(int n);

// Where a point x lands on a bilinear face (current positions xm): the closest point's (s, t),
// found by Newton's method from the face's centre, the gap along the face's unit normal, and
// whether (s, t) lies within [-1, 1]^2 (to 1e-10). Nothing if Newton does not converge (a face
// so warped that the closest point is not unique).
struct FaceProjection {
  Eigen::Vector2d st;
  Eigen::Vector3d normal;  // unit, the right-hand normal of the face's node order
  double gap = 0;          // (x - x_m(s, t)) . normal [m]
  bool inside = false;
};
std::optional<FaceProjection> projectOntoFace(const loads::FaceNodes &xm, const Eigen::Vector3d &x);

// The forces of one slave point (xs: the slave face's current nodes) on the master face xm, with
// the multiplier lambda [Pa] and penalty eps [Pa/m]; the point's gap, pressure and area in
// `point`. A point whose projection leaves the master face, or does not converge, carries nothing
// (gap +infinity). K, if given, is d f / d u.
PairForces pairPointForces(const loads::FaceNodes &xs, const SlavePoint &q, const loads::FaceNodes &xm,
                           double lambda, double eps, ContactPointState *point = nullptr,
                           PairTangent *K = nullptr);

}  // namespace glossa::contact
