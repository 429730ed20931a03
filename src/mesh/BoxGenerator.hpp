#pragma once
// A structured hexahedral mesh of an axis-aligned box: the mesh of patch tests, uniaxial
// tension and the cube scenes of the paper (doc/meshes.md).

#include <Eigen/Core>
#include <array>

#include "mesh/HexMesh.hpp"

namespace glossa::mesh {

// cells[0] x cells[1] x cells[2] equal hexes filling [origin, origin + lengths].
// Node (i, j, k) has id i + (nx+1)(j + (ny+1)k), element (i, j, k) has id i + nx(j + ny k).
// Face sets and node sets "xmin", "xmax", "ymin", "ymax", "zmin", "zmax"; element set "all";
// named point "origin" (node 0). Other named points come from the deck.
// Throws std::invalid_argument naming the parameter if a cell count is < 1 or a length is
// not a positive finite number (or the origin is not finite).
HexMesh generateBox(const Eigen::Vector3d &origin, const Eigen::Vector3d &lengths,
                    const std::array<int, 3> &cells);

}  // namespace glossa::mesh
