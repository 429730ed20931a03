#pragma once
// A surface file read by its extension: .obj (Wavefront) or .stl (ASCII or binary), in any case.

#include <string>

#include "contact/TriangleSurface.hpp"

namespace glossa::contact {

// `scale` converts the file's length unit to metres. Throws SurfaceError for another extension
// and for what the readers refuse.
TriangleSurface readSurface(const std::string &path, double scale = 1.0);

}  // namespace glossa::contact
