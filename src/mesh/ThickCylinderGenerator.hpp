#pragma once
// A quarter of a thick-walled cylinder (verification of follower pressure, doc/loads.md): radii
// [innerRadius, outerRadius], angle [0, pi/2] from +x towards +y, height [0, height] along z.
// Cells are uniform in r, angle and z. Face and node sets: inner, outer, y0 (the plane y = 0),
// x0 (the plane x = 0), zmin, zmax; element set "all"; named point "inner" at (innerRadius, 0, 0).

#include <array>

#include "mesh/HexMesh.hpp"

namespace glossa::mesh {

// Throws std::invalid_argument unless 0 < innerRadius < outerRadius, height > 0 and every
// cell count >= 1.
HexMesh generateThickCylinder(double innerRadius, double outerRadius, double height,
                              const std::array<int, 3> &cells /* radial, circumferential, axial */);

} // namespace glossa::mesh
