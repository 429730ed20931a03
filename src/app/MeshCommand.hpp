#pragma once
// `glossa mesh FILE [--format F] [--refine N] [--json] [--output DIR|OUT.msh|OUT.inp]` (doc/meshes.md): reads any
// supported mesh (doc/meshes.md), optionally refines it, and reports what a user checks before
// building a deck on it: node and element counts, every set with its size (and an element set's
// volume), the total volume and the range of the scaled Jacobian. --output DIR writes the mesh as
// XDMF/HDF5 with one 0/1 cell field per element set, for ParaView; --output OUT.msh or OUT.inp
// writes it as MSH 4.1 or Abaqus with all its sets, face sets included (mesh/MeshWriter.hpp).

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace glossa::app {

struct MeshCommandOptions {
  std::string format = "auto";
  int refine = 0;
  std::filesystem::path output; // empty: no files; .msh/.inp: a mesh file; no extension: an XDMF directory
};

// The report as JSON (what --json prints). Throws std::runtime_error (file:line: reason) for a
// file the readers refuse, io::DeckError for an --output with another extension (out.vtk) that is
// not an existing directory.
nlohmann::json describeMesh(const std::string &file, const MeshCommandOptions &options);

// Human-readable text of the report.
std::string meshReportText(const nlohmann::json &report);

} // namespace glossa::app
