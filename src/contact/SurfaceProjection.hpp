#pragma once
// The contact quantities of a point against one triangle of a surface: the closest point, the
// normal out of the obstacle, the signed gap and the normal's derivative (contact/Obstacle.hpp).
//  - On the triangle's interior: the triangle's normal; the gap (x - p) . n; dNormal = 0.
//  - On an edge or a corner: n = +-(x - p) / |x - p|, signed by the pseudonormal of that edge or
//    corner (TriangleSurface), so that a point inside a closed surface, or behind an open
//    sheet, gets a negative gap. Then gap = +-|x - p| and, as p slides along an edge e,
//    dNormal = (I - n n - e e) / gap; at a corner p is fixed and dNormal = (I - n n) / gap.
//  - On the free boundary of an open sheet (an edge with one triangle, or a corner on one):
//    x lies beside the sheet, beyond its extent, not through it, so the sign is +: apart. (With
//    the face's sign, two nodes of the tongue at rest beside the free lateral edges of the
//    pharyngeal wall, 61 and 474, would be 14 and 13 mm "inside" a sheet no tongue edge crosses.)

#include <cstddef>

#include "contact/Obstacle.hpp"
#include "contact/PointTriangle.hpp"
#include "contact/TriangleSurface.hpp"

namespace glossa::contact {

// Whether the closest point `pr` of triangle t lies on the free boundary of an open sheet (an
// edge with one triangle, or a corner on one): beside the sheet, where the faceted rule stands
// for every normal field.
bool onFreeBoundary(const TriangleSurface &surface, std::size_t t, const TriangleProjection &pr);

// `besideFreeBoundary`, if given, says whether p is on the free boundary of an open sheet.
ClosestPoint projectOnTriangle(const TriangleSurface &surface, std::size_t triangle, const Eigen::Vector3d &x,
                               bool *besideFreeBoundary = nullptr);

// The triangle closest to x by visiting every triangle (linear in their number): for one-off
// queries such as orienting a surface, where no search tree is worth building.
std::size_t closestTriangleByScan(const TriangleSurface &surface, const Eigen::Vector3d &x);

}  // namespace glossa::contact
