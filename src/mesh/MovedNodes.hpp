#pragma once
// Node positions that replace some of an imported mesh's: a mesh file kept as published, with
// a few of its nodes moved by a separate file (e.g. the tongue's interior nodes moved to mend its
// most distorted elements, inputs/tongue/mend_tongue.py). Lines "id x y z" in metres, the file's
// node ids; '!' and '#' start comments.

#include <string>

#include "mesh/ImportedMesh.hpp"

namespace glossa::mesh {

// Moves the nodes the file names and checks every element again (distinct nodes, a positive
// Jacobian at each Gauss point). Throws std::runtime_error "file:line: reason" for a malformed
// line, an id not in the mesh or one given twice, and names the element a move inverts.
void moveNodes(const std::string &file, ImportedMesh &imported);

}  // namespace glossa::mesh
