#pragma once
// Cook's membrane: the tapered cantilever used to verify nearly incompressible elements
// (Cook 1974; 3-D set-up of deal.II step-44, doc/meshes.md).

#include "mesh/HexMesh.hpp"

namespace glossa::mesh {

// The trapezoid with corners (0,0), (48,44), (48,60), (0,44) in the x-y plane, in millimetres
// times `scale` (1e-3 for metres), extruded in z over [0, thickness * scale]. It is the
// bilinear image of a cellsXY x cellsXY x cellsZ structured grid: grid index i runs from the
// clamped edge x = 0 to the loaded edge x = 48, j from the lower slanted edge to the upper one,
// k from z = 0 to z = thickness. Node and element ids as in generateBox.
// Face sets and node sets: "clamped" (x = 0), "loaded" (x = 48), "bottom" (lower slanted edge,
// (0,0)-(48,44)), "top" (upper slanted edge, (0,44)-(48,60)), "front" (z = 0), "back"
// (z = thickness); element set "all"; named point "tip" = the node at (48, 60, 0) * scale.
// Throws std::invalid_argument naming the parameter if a cell count is < 1 or thickness or
// scale is not a positive finite number.
HexMesh generateCookMembrane(int cellsXY, int cellsZ, double thickness, double scale);

}  // namespace glossa::mesh
