#pragma once
// A surface file (OBJ, STL) that cannot be used as a rigid obstacle: unreadable, or a triangle
// mesh that is degenerate, non-manifold or inconsistently oriented. Its message names the file,
// the line (or byte offset in a binary file) and what was found. It is a bad input file like a
// bad mesh file, so it derives from mesh::MeshError and `glossa` exits 2 on it.

#include "mesh/MeshError.hpp"

namespace glossa::contact {

class SurfaceError : public mesh::MeshError {
 public:
  using mesh::MeshError::MeshError;
};

}  // namespace glossa::contact
