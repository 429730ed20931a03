#pragma once
// Which side of a surface the body is on, i.e. where the normals must point (out of the
// obstacle, doc/contact.md "Normals"):
//  - AsStored: the file's winding (right-hand rule) as it is;
//  - Outward: a closed surface (a bone) wound so that its normals point out of the volume it
//    encloses (its signed volume positive); refused for an open one, which encloses none;
//  - TowardPoint: wound so that a given point, known to be on the body's side (a point of the
//    tongue for the palate sheet), has a positive gap.
// The whole surface is kept or flipped: its orientation is consistent (TriangleSurface).

#include <Eigen/Core>

#include "contact/TriangleSurface.hpp"

namespace glossa::contact {

enum class NormalSide { AsStored, Outward, TowardPoint };

// Throws SurfaceError for Outward on an open surface, and for a point on the surface itself or
// beside its free edge (its closest point on the free boundary), which faces neither side.
TriangleSurface orientNormals(TriangleSurface surface, NormalSide side,
                              const Eigen::Vector3d &bodyPoint = Eigen::Vector3d::Zero());

}  // namespace glossa::contact
