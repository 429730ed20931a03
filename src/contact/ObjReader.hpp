#pragma once
// Wavefront OBJ surfaces: `v x y z` (a fourth number is the homogeneous weight, six are a
// vertex colour, ignored), `f` with `v`, `v/vt`, `v//vn` or `v/vt/vn` corners, negative
// (relative) indices, polygons fan-triangulated from their first corner, `#` comments. `vt`,
// `vn`, `vp`, `g`, `o`, `s`, `usemtl` and `mtllib` are read past: the normals come from the
// winding. Any other statement (`l`, `p`, curves) is refused rather than skipped.

#include <string>

#include "contact/TriangleSurface.hpp"

namespace glossa::contact {

// `scale` converts the file's length unit to metres (1 for a file in metres, 1e-3 in mm).
// Throws SurfaceError naming the file, the line and what was found.
TriangleSurface readObj(const std::string &path, double scale = 1.0);

}  // namespace glossa::contact
