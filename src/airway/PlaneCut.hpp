#pragma once
// The curves where a plane cuts a triangulated surface: each triangle whose corners lie on both
// sides gives a segment between the points where two of its edges cross the plane, and the
// segments are chained through the edges they share into polylines (open where the surface ends,
// closed round a tube). A corner exactly on the plane counts as on its positive side (a fixed
// tie-break, so that a shared edge is crossed, or not, alike for both its triangles and the
// chains never break).

#include <Eigen/Core>
#include <array>
#include <vector>

#include "airway/SectionPlane.hpp"

namespace glossa::airway {

struct CutCurve {
  std::vector<Eigen::Vector3d> points;  // in order along the curve
  bool closed = false;                  // the last point joins the first
  // The distance from x to the nearest point of the curve's segments.
  double distanceTo(const Eigen::Vector3d &x) const;
};

// Every curve where `plane` cuts the triangles (0-based indices into `vertices`).
std::vector<CutCurve> cutSurface(const std::vector<Eigen::Vector3d> &vertices,
                                 const std::vector<std::array<int, 3>> &triangles, const SectionPlane &plane);

// The curve of `curves` nearest to `x`, or nullptr if there is none.
const CutCurve *nearestCurve(const std::vector<CutCurve> &curves, const Eigen::Vector3d &x);

}  // namespace glossa::airway
