#pragma once
// The topology shared by the box and Cook-membrane generators: an nx x ny x nz block of
// hexahedra whose geometry is any orientation-preserving map of the grid points.

#include <Eigen/Core>
#include <array>
#include <functional>
#include <string>

#include "mesh/HexMesh.hpp"

namespace glossa::mesh {

// Names of the six sides of the block, in the order i = 0, i = nx, j = 0, j = ny, k = 0, k = nz.
using BlockSideNames = std::array<std::string, 6>;

// Builds the block: node (i, j, k) has id i + (nx+1)(j + (ny+1)k) and sits at
// position(i, j, k); element (i, j, k) has id i + nx(j + ny k) and VTK local order, so the
// Jacobian is positive when position is orientation-preserving (right-handed in i, j, k).
// Each side gets a face set (sorted) and the node set of its faces; element set "all" holds
// every element. No named points. Throws std::invalid_argument if a cell count is < 1.
HexMesh structuredHexGrid(const std::array<int, 3> &cells,
                          const std::function<Eigen::Vector3d(int, int, int)> &position,
                          const BlockSideNames &sideNames);

}  // namespace glossa::mesh
