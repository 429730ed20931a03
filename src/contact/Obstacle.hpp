#pragma once
// A rigid obstacle as the contact kernels see it: for a point x of the body's surface, the
// closest point of the obstacle's surface, its normal and the signed gap. Analytic shapes
// (plane, sphere, cylinder) and triangulated surfaces (OBJ, STL) implement it; a rigid motion
// in time wraps any of them. Eigen only, so the kernels and their tests stay free of Trilinos.
//
// Conventions (doc/contact.md):
//  - `normal` is the unit normal of the obstacle's surface at `point`, pointing to the side
//    where the body may be (out of the obstacle).
//  - gap = (x - point) . normal: positive apart, negative where x has entered the obstacle.
//  - dNormal = d normal / d x at x, for the consistent tangent: zero for a plane and on a
//    triangle's interior; (I - n n) / (R + gap) for a sphere of radius R seen from outside.
//  - dGap = d gap / d x: the normal itself wherever x - point lies along the normal (every
//    obstacle's exact closest point), so left empty there; a surface with smoothed normals, whose
//    normal is not along x - point, gives it (contact/SmoothedProjection.hpp).

#include <Eigen/Core>
#include <optional>

namespace glossa::contact {

struct ClosestPoint {
  Eigen::Vector3d point;   // on the obstacle's surface
  Eigen::Vector3d normal;  // unit, out of the obstacle
  double gap = 0;          // (x - point) . normal [m]
  Eigen::Matrix3d dNormal = Eigen::Matrix3d::Zero();
  std::optional<Eigen::Vector3d> dGap;  // empty: dg/dx = normal
  Eigen::Vector3d gapGradient() const { return dGap ? *dGap : normal; }
};

class Obstacle {
public:
  virtual ~Obstacle() = default;
  // The closest point to x if the obstacle's surface lies within searchRadius of x [m];
  // nothing otherwise (the point cannot touch in this step).
  virtual std::optional<ClosestPoint> closest(const Eigen::Vector3d &x, double searchRadius) const = 0;
  // Where a material point of the obstacle, given in its own frame, is now, and back: the
  // identity for an obstacle at rest. Friction and tied contact keep the obstacle's point a contact
  // point sticks to in this frame, so that it moves with a moving obstacle.
  virtual Eigen::Vector3d toWorld(const Eigen::Vector3d &X) const { return X; }
  virtual Eigen::Vector3d toBody(const Eigen::Vector3d &x) const { return x; }
};

} // namespace glossa::contact
