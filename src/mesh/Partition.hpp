#pragma once
// Element ownership for distributed assembly. The mesh is replicated on every rank
// (HexMesh.hpp); this decides which rank assembles which element.

#include <vector>

#include "mesh/HexMesh.hpp"

namespace glossa::mesh {

// Owner rank in [0, parts) of every element, by recursive coordinate bisection of the element
// centroids (mean of the eight nodes): a set of elements destined for c parts is split across
// the longest extent of its centroids' bounding box (lowest axis on a tie) into halves destined
// for floor(c/2) and c - floor(c/2) parts, with sizes chosen so that every final part holds
// floor(n/parts) or ceil(n/parts) elements. Centroids are ordered by coordinate and then by
// element id, so the result is deterministic. Any two parts are separated by an axis-aligned
// plane; a part need not be face-connected when a cut runs through a slab of equal centroids
// (structured meshes with part counts that do not divide the slabs). parts > numElements() is
// allowed (some parts are then empty). Throws std::invalid_argument if parts < 1.
std::vector<int> partitionElements(const HexMesh &mesh, int parts);

}  // namespace glossa::mesh
