#pragma once
// A quarter of a solid cylinder resting on the plane y = 0, graded towards the line where it
// touches it: the body of Hertz's cylinder-on-a-plane contact (doc/contact.md, "Hertz"). The
// cylinder of radius R has its axis through (0, R, 0) along z; the quarter kept is x >= 0 (the
// plane x = 0 a symmetry plane) and y <= R (the flat top y = R, through the axis, takes the load),
// z in [0, height]. Its lowest line, x = y = 0, is where contact starts.
//
// The cross-section is an O-grid of three blocks, so that every boundary node lies on the circle
// and every element corner stays far from flat: an inner square [0, R/2]^2 about the axis, and
// two blocks between it and the arc, cut by the 45 degree ray. Their lines run along rays from
// the axis. The contact block (angles 0..45 degrees from straight down) has `band` equal cells
// (in angle) along the arc from the lowest line to x = bandWidth, where contact is expected, then
// `contact` cells growing geometrically from that size to 45 degrees; the side block (45..90
// degrees) has `side` equal cells. Both have `radial` cells along each ray, growing geometrically
// from the arc, where a cell is as long radially as a band cell is along the arc (square cells
// where contact is), or equal cells where `radial` equal cells are already that fine. Doubling
// every count halves every cell, so a family of meshes follows the circle at every refinement
// (splitting hexahedra would keep the coarse facets).
//
// Face and node sets: arc (the curved surface), top (y = R), x0 (x = 0), zmin, zmax; element
// set "all"; named points "lowest" at the origin and "axis" at (0, R, 0).

#include <array>

#include "mesh/HexMesh.hpp"

namespace glossa::mesh {

struct QuarterCylinderCells {
  int band = 8;     // along the arc from the lowest line to x = bandWidth, equal
  int contact = 8;  // along the arc from the band to 45 degrees, growing
  int side = 4;     // along the arc from 45 to 90 degrees
  int radial = 12;  // along each ray from the inner square to the arc, graded towards the arc
  int axial = 1;    // along z
};

// Throws std::invalid_argument unless radius and height are positive and finite, 0 < bandWidth <
// radius / sqrt 2 and every cell count >= 1.
HexMesh generateQuarterCylinder(double radius, double height, const QuarterCylinderCells &cells, double bandWidth);

} // namespace glossa::mesh
