#pragma once
// A cross-section plane of the airway: a point on the centreline, the unit normal (the
// centreline's direction there) and two in-plane unit axes, lateral (u, left to right) and
// depth (v, from the tongue towards the wall). Points of the plane are written (u, v) about
// `origin`.

#include <Eigen/Core>

namespace glossa::airway {

struct SectionPlane {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();
  Eigen::Vector3d lateral = Eigen::Vector3d::UnitY();
  Eigen::Vector3d depth = Eigen::Vector3d::UnitZ();

  // Signed distance of x from the plane along the normal.
  double distance(const Eigen::Vector3d &x) const { return normal.dot(x - origin); }
  // (u, v) of x's projection onto the plane.
  Eigen::Vector2d inPlane(const Eigen::Vector3d &x) const {
    const Eigen::Vector3d d = x - origin;
    return {lateral.dot(d), depth.dot(d)};
  }
  Eigen::Vector3d at(const Eigen::Vector2d &uv) const { return origin + uv.x() * lateral + uv.y() * depth; }
};

// The plane through `origin` with normal `normal`, its lateral axis `lateral` made
// perpendicular to the normal, and its depth axis normal x lateral turned, if need be, to point
// along `towardWall`. Throws std::invalid_argument if the normal is zero or parallel to the
// lateral direction.
SectionPlane makeSectionPlane(const Eigen::Vector3d &origin, const Eigen::Vector3d &normal,
                              const Eigen::Vector3d &lateral, const Eigen::Vector3d &towardWall);

}  // namespace glossa::airway
