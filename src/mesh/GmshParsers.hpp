#pragma once
// The MSH parsers behind readGmsh (GmshReader.hpp), one per encoding; each reads sections and
// hands nodes and elements to a gmsh::Assembly, which owns the rules for turning them into a
// mesh. readGmsh picks the parser by the $MeshFormat line's file-type.

#include <string>

#include "mesh/ImportedMesh.hpp"

namespace glossa::mesh::gmsh {

// MSH 2.2 or 4.1 with file-type 0 (ASCII); any other version is refused.
ImportedMesh parseAscii(const std::string &file);
// MSH 2.2 or 4.1 with file-type 1 (binary, data-size 8, little-endian as the marker shows).
ImportedMesh parseBinary(const std::string &file);

}  // namespace glossa::mesh::gmsh
