#include "mesh/GmshReader.hpp"

#include <fstream>

#include "mesh/GmshParsers.hpp"
#include "mesh/ImportSupport.hpp"

namespace glossa::mesh {

namespace {

// Whether the file's $MeshFormat line says file-type 1. Only the first lines are looked at;
// anything that does not look like a binary MSH header goes to the ASCII parser, whose
// messages then say what is wrong.
bool saysBinary(const std::string &file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) importing::fail(file, 0, "cannot open");
  std::string line;
  int seen = 0;
  bool format = false;
  while (seen < 2 && std::getline(in, line)) {
    const std::string t = importing::trim(line);
    if (t.empty()) continue;
    ++seen;
    if (seen == 1) {
      format = t == "$MeshFormat";
      continue;
    }
    const auto fields = importing::splitWhitespace(t);
    return format && fields.size() == 3 && fields[1] == "1";
  }
  return false;
}

}  // namespace

ImportedMesh readGmsh(const std::string &file) {
  return saysBinary(file) ? gmsh::parseBinary(file) : gmsh::parseAscii(file);
}

}  // namespace glossa::mesh
