#include "mesh/MeshFile.hpp"

#include <cctype>
#include <functional>
#include <map>
#include <stdexcept>

#include "mesh/AbaqusReader.hpp"
#include "mesh/AnsysReader.hpp"
#include "mesh/GmshReader.hpp"
#include "mesh/MeshError.hpp"

namespace glossa::mesh {

namespace {

std::string extension(const std::string &path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot);
  for (char &c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

std::string withExtension(const std::string &path, const std::string &ext) {
  return path.substr(0, path.find_last_of('.')) + ext;
}

ImportedMesh readAnsysPair(const std::string &path) {
  const std::string e = extension(path);
  if (e == ".node") return readAnsysMesh(path, withExtension(path, ".elem"));
  if (e == ".elem") return readAnsysMesh(withExtension(path, ".node"), path);
  throw MeshError(path + ": an ANSYS mesh is named by its .node or .elem file");
}

// The explicit factory map (doc/developing.md, style): format name -> reader.
const std::map<std::string, std::function<ImportedMesh(const std::string &)>> &readers() {
  static const std::map<std::string, std::function<ImportedMesh(const std::string &)>> map = {
      {"abaqus", readAbaqus}, {"ansys", readAnsysPair}, {"gmsh", readGmsh}};
  return map;
}

}  // namespace

const std::vector<std::string> &meshFileFormats() {
  static const std::vector<std::string> names = {"abaqus", "ansys", "gmsh"};
  return names;
}

std::string meshFormatOfPath(const std::string &path) {
  const std::string e = extension(path);
  if (e == ".msh") return "gmsh";
  if (e == ".inp") return "abaqus";
  if (e == ".node" || e == ".elem") return "ansys";
  throw MeshError(path + ": cannot tell the mesh format from the extension '" + e +
                           "' (known: .msh gmsh, .inp abaqus, .node/.elem ansys); give the format");
}

ImportedMesh readMeshFile(const std::string &path, const std::string &format) {
  const std::string name = format == "auto" ? meshFormatOfPath(path) : format;
  const auto it = readers().find(name);
  if (it == readers().end()) {
    throw MeshError("unknown mesh format '" + name + "' (known: abaqus, ansys, gmsh, auto)");
  }
  return it->second(path);
}

}  // namespace glossa::mesh
