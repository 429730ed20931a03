#pragma once
// An octant of a thick-walled spherical shell, x, y, z >= 0, radii [innerRadius, outerRadius]:
// the verification scene of a pressurised sphere, whose inflation has a closed form and a
// pressure maximum (doc/loads.md). The octant's surface is cut into three patches, one per
// coordinate direction (where that coordinate is the largest), each an n x n grid of equal
// angles projected from a face of the unit cube (a "cubed sphere"), and the shell into
// `radialCells` uniform layers: 3 n^2 radialCells hexahedra.
// Face and node sets: inner, outer, x0, y0, z0 (the symmetry planes); element set "all"; named
// points inner and outer on the x axis, at (innerRadius, 0, 0) and (outerRadius, 0, 0).

#include "mesh/HexMesh.hpp"

namespace glossa::mesh {

// Throws std::invalid_argument unless 0 < innerRadius < outerRadius (finite) and both cell
// counts are >= 1.
HexMesh generateThickSphere(double innerRadius, double outerRadius, int radialCells, int cellsPerPatchSide);

} // namespace glossa::mesh
