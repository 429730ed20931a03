#pragma once
// One entry point for the deck and the `glossa mesh` command: a mesh file and its format name.

#include <string>
#include <vector>

#include "mesh/ImportedMesh.hpp"

namespace glossa::mesh {

// The format names a deck may give: "gmsh" (.msh), "abaqus" (.inp), "ansys" (.node + .elem).
const std::vector<std::string> &meshFileFormats();

// "gmsh", "abaqus" or "ansys" from the extension (.msh, .inp, .node or .elem); throws
// std::runtime_error naming the path and the known extensions otherwise.
std::string meshFormatOfPath(const std::string &path);

// Reads `path` as `format` ("auto" = by extension). For "ansys", path is the .node or the .elem
// file and the other one is the same path with the other extension; components, fibres and
// node lists are read separately (readAnsysModel). Throws std::runtime_error for an unknown
// format (listing the known ones) and whatever the reader throws.
ImportedMesh readMeshFile(const std::string &path, const std::string &format = "auto");

}  // namespace glossa::mesh
