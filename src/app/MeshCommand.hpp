#pragma once
// `glossa mesh FILE [--format F] [--refine N] [--json] [--output DIR]` (issue 7): reads any
// supported mesh (doc/meshes.md), optionally refines it, and reports what a user checks before
// building a deck on it: node and element counts, every set with its size (and an element set's
// volume), the total volume and the range of the scaled Jacobian. --output writes the mesh as
// XDMF/HDF5 with one 0/1 cell field per element set, for ParaView.

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace glossa::app {

struct MeshCommandOptions {
  std::string format = "auto";
  int refine = 0;
  std::filesystem::path output; // empty: no files
};

// The report as JSON (what --json prints). Throws std::runtime_error (file:line: reason) for a
// file the readers refuse.
nlohmann::json describeMesh(const std::string &file, const MeshCommandOptions &options);

// Human-readable text of the report.
std::string meshReportText(const nlohmann::json &report);

} // namespace glossa::app
