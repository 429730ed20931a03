#pragma once
// STL surfaces, ASCII or binary. The format is told by the size, not by the first word: a binary
// file is 84 + 50 n bytes for the n triangles its bytes 80-83 count, and its 80-byte header may
// itself start with "solid"; any other file must be ASCII (`solid` ... `endsolid`, one or more
// solids). STL stores each triangle's corners on their own, so corners with identical
// coordinates are merged into one vertex (the edges' checks need shared vertices). The stored
// facet normals are not used: the normals come from the winding, as the format specifies.

#include <string>

#include "contact/TriangleSurface.hpp"

namespace glossa::contact {

// `scale` converts the file's length unit to metres. Throws SurfaceError naming the file and
// the line (ASCII) or byte offset (binary) and what was found.
TriangleSurface readStl(const std::string &path, double scale = 1.0);

}  // namespace glossa::contact
