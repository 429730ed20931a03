#pragma once
// The closest point of a surface at a fixed distance R from a centre or an axis (a sphere, a
// cylinder): with c the centre or the point of the axis nearest to x and P the projector onto
// the directions the radius spans (I for a sphere, I - e e for a cylinder of axis e),
//   d = P (x - c),  r = |d|,  n = s d / r,  gap = s (r - R),  dNormal = s (P - n n) / r,
// where s = +1 for a body outside the surface and s = -1 for a body inside it (a cavity).
// Eigen only.

#include <optional>

#include "contact/Obstacle.hpp"

namespace glossa::contact {

// Which side of a closed analytic surface the body is on: the normal points to it.
enum class BodySide { outside, inside };

// The closest point as above, if |gap| <= searchRadius. Nothing on the centre or the axis itself
// (r = 0), where every point of the surface is equally close and no direction is the normal:
// such a point is at depth R, far beyond any penalty's intended penetration.
std::optional<ClosestPoint> radialClosestPoint(const Eigen::Vector3d &x, const Eigen::Vector3d &c,
                                               const Eigen::Matrix3d &P, double R, BodySide side,
                                               double searchRadius);

}  // namespace glossa::contact
