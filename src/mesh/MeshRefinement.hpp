#pragma once
// Uniform refinement of hexahedral meshes: every hexahedron split into eight, so that coarse,
// medium and fine meshes of one model come from one file (doc/meshes.md, "Refinement").

#include "mesh/HexMesh.hpp"

namespace glossa::mesh {

// Splits every hexahedron into 2 x 2 x 2 children, `levels` times (0 returns a copy).
// Nodes: the old nodes keep their ids 0..N-1, so node sets and named points keep their nodes;
// then one new node per distinct edge (its midpoint), per distinct face (mean of its four
// nodes) and per element (mean of its eight nodes), each shared by all elements touching that
// edge or face. These are the trilinear map's values at the parameter midpoints, so each child
// is exactly the parent's map restricted to an octant: the refined mesh covers the same
// region, and volumes are preserved up to round-off for any (not only affine) hexahedra.
// Elements: child (i, j, k) in {0,1}^3 of element e (i along xi, j along eta, k along zeta)
// has id 8e + i + 2j + 4k, VTK order and the parent's orientation.
// Sets: an element set holds the children of its elements (x8); a face (e, f) of a face set
// becomes the four children's faces with the same local face f (x4); a node set keeps its
// nodes and gains each new node all of whose defining nodes (the edge's two, the face's four,
// the element's eight) are in the set -- for a node set made of a face set's nodes this is
// the node set of the refined faces. Named points keep their node and position.
// Throws std::invalid_argument if levels < 0.
HexMesh refineUniformly(const HexMesh &mesh, int levels);

// The node positions refineUniformly(mesh, levels) would have if `mesh`'s nodes were at
// `positions` (one per node of `mesh`): a geometry given on the mesh as read, such as a
// zero-strain configuration (doc/tongue.md), carried to its refinement. The numbering of the
// new nodes depends on the connectivity only, so it is that of refineUniformly(mesh, levels).
// Throws std::invalid_argument if positions.size() != mesh.numNodes() or levels < 0.
std::vector<Eigen::Vector3d> refinedPositions(const HexMesh &mesh, std::vector<Eigen::Vector3d> positions,
                                              int levels);

}  // namespace glossa::mesh
