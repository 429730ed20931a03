#pragma once
// A slave face's contact points segmented against the master faces it may meet (doc/contact.md,
// "Deformable pairs and self-contact"): in the slave face's (s, t) square, the master faces'
// edges, projected there from the reference configuration, cut the square into convex cells;
// each cell is split into triangles carrying a 6-point rule of degree 4 (Dunavant). Inside a cell
// the master's shape functions have no kink, so the master's nodal forces, which the slave's
// points integrate, are exact for a flat interface under a uniform pressure: the two-block patch
// test passes to round-off. The cells are fixed in the reference configuration; after sliding by
// a fraction of a face they no longer align with the master's edges, and the points become a
// generic rule of as many points. Eigen only.

#include <vector>

#include "contact/PairContact.hpp"

namespace glossa::contact {

// The points of a slave face (reference nodes slaveX) cut by the edges of the faces in masterX
// (reference nodes), weights summing to 4 (the square's area). A master face whose nodes cannot
// be projected onto the slave face's plane (Newton fails) cuts nothing.
std::vector<SlavePoint> segmentedSlavePoints(const loads::FaceNodes &slaveX,
                                             const std::vector<loads::FaceNodes> &masterX);

}  // namespace glossa::contact
