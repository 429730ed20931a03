#include "app/MeshCommand.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <utility>
#include <vector>

#include "io/deck/DeckError.hpp"
#include "io/output/OutputError.hpp"
#include "io/output/ResultWriter.hpp"
#include "mesh/MeshChecks.hpp"
#include "mesh/MeshError.hpp"
#include "mesh/MeshFile.hpp"
#include "mesh/MeshQuality.hpp"
#include "mesh/MeshRefinement.hpp"
#include "mesh/MeshWriter.hpp"

namespace glossa::app {

namespace {
// The report names this many elements of the smallest scaled Jacobian.
constexpr std::size_t kWorstElementsShown = 5;

// --output names a mesh file (.msh, .inp) or a directory for XDMF. Any other extension is far more
// likely a format glossa does not write (out.vtk) than a directory's name: it is refused, before
// the mesh is read, rather than made a directory; an existing directory or a trailing / is taken.
void checkOutputName(const std::filesystem::path &output) {
  const std::string extension = output.extension().string();
  if (extension.empty() || extension == ".msh" || extension == ".inp" || std::filesystem::is_directory(output)) return;
  throw io::DeckError("--output " + output.string() + ": glossa mesh writes OUT.msh (Gmsh), OUT.inp (Abaqus) or a " +
                      "directory DIR (XDMF for ParaView), not " + extension + " files; for a directory of that " +
                      "name, end it with /");
}
} // namespace

nlohmann::json describeMesh(const std::string &file, const MeshCommandOptions &options) {
  checkOutputName(options.output);
  mesh::ImportedMesh imported = mesh::readMeshFile(file, options.format);
  mesh::HexMesh m = std::move(imported.mesh);
  if (options.refine > 0) m = mesh::refineUniformly(m, options.refine);
  nlohmann::json r;
  r["file"] = file;
  r["refine"] = options.refine;
  r["notes"] = imported.notes;
  r["nodes"] = m.nodes.size();
  r["elements"] = m.numElements();
  r["volume"] = mesh::meshVolume(m);
  // Every element's scaled Jacobian once, for the range, the worst elements and the XDMF field.
  // (The readers refuse a mesh without elements.)
  const std::vector<double> quality = mesh::scaledJacobians(m);
  const auto [sjMin, sjMax] = std::minmax_element(quality.begin(), quality.end());
  r["scaled_jacobian"] = {{"min", *sjMin}, {"max", *sjMax}};
  // The worst elements by name: near-degenerate ones are where a large deformation folds a
  // corner first (the tongue's under airway suction, doc/airway.md).
  std::vector<std::size_t> order(quality.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const std::size_t shown = std::min(kWorstElementsShown, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(shown), order.end(),
                    [&](std::size_t a, std::size_t b) { return quality[a] < quality[b]; });
  nlohmann::json worst = nlohmann::json::array();
  for (std::size_t k = 0; k < shown; ++k) worst.push_back({{"element", order[k]}, {"value", quality[order[k]]}});
  r["scaled_jacobian"]["worst"] = worst;
  // What a run would refuse (doc/meshes.md, "Before a run").
  const mesh::MeshCheckReport checks = mesh::checkMesh(m);
  r["checks"] = {{"unused_nodes", checks.unusedNodes.size()},
                 {"coincident_node_pairs", checks.coincidentNodes.size()},
                 {"duplicate_elements", checks.duplicateElements.size()},
                 {"inverted_corner_elements", checks.invertedCorners.size()},
                 {"parts", mesh::meshParts(m).second}};
  nlohmann::json sets = nlohmann::json::object();
  for (const auto &[name, elements] : m.elementSets) {
    double v = 0.0;
    for (const auto e : elements) v += mesh::elementVolume(m.elementCoordinates(e));
    sets["element"][name] = {{"size", elements.size()}, {"volume", v}};
  }
  for (const auto &[name, faces] : m.faceSets) sets["face"][name] = {{"size", faces.size()}};
  for (const auto &[name, nodes] : m.nodeSets) sets["node"][name] = {{"size", nodes.size()}};
  r["sets"] = sets;
  const std::string extension = options.output.extension().string();
  if (extension == ".msh" || extension == ".inp") {
    // A mesh file with every set, face sets included (MeshWriter.hpp), for Gmsh or a solver.
    try {
      extension == ".msh" ? mesh::writeGmsh(m, options.output.string()) : mesh::writeAbaqus(m, options.output.string());
    } catch (const mesh::MeshError &) {
      throw;
    } catch (const std::runtime_error &e) {
      throw io::OutputError(e.what());
    }
    r["written"] = options.output.string();
  } else if (!options.output.empty()) {
    std::vector<std::array<std::int64_t, 8>> hexes(m.elements.begin(), m.elements.end());
    io::ResultWriter writer(options.output, "mesh", m.nodes, hexes);
    std::vector<io::Field> cells;
    for (const auto &[name, elements] : m.elementSets) {
      std::vector<double> member(m.numElements(), 0.0);
      for (const auto e : elements) member[static_cast<std::size_t>(e)] = 1.0;
      cells.push_back({"set_" + name, 1, member});
    }
    cells.push_back({"scaled_jacobian", 1, quality});
    writer.writeStep(0.0, {}, cells);
    r["written"] = (options.output / "mesh.xdmf").string();
  }
  return r;
}

std::string meshReportText(const nlohmann::json &r) {
  std::ostringstream s;
  s << r.at("file").get<std::string>();
  if (r.at("refine").get<int>() > 0) s << " (refined " << r.at("refine") << "x)";
  s << "\n  nodes " << r.at("nodes") << "  elements " << r.at("elements") << "  volume " << r.at("volume").get<double>()
    << " m^3\n  scaled Jacobian " << r.at("scaled_jacobian").at("min").get<double>() << " .. "
    << r.at("scaled_jacobian").at("max").get<double>() << "; smallest at elements (numbered from 0)";
  for (const auto &w : r.at("scaled_jacobian").at("worst"))
    s << " " << w.at("element").get<std::size_t>() << " (" << w.at("value").get<double>() << ")";
  s << "\n";
  const auto &c = r.at("checks");
  s << "  parts " << c.at("parts") << "  unused nodes " << c.at("unused_nodes") << "  coincident node pairs "
    << c.at("coincident_node_pairs") << "  duplicate elements " << c.at("duplicate_elements")
    << "  elements with an inverted corner " << c.at("inverted_corner_elements") << "\n";
  if (r.contains("notes"))
    for (const auto &note : r.at("notes")) s << "  note: " << note.get<std::string>() << "\n";
  const auto &sets = r.at("sets");
  for (const char *kind : {"element", "face", "node"}) {
    if (!sets.contains(kind)) continue;
    for (const auto &[name, info] : sets.at(kind).items()) {
      s << "  " << kind << " set " << name << ": " << info.at("size");
      if (info.contains("volume")) s << "  volume " << info.at("volume").get<double>();
      s << "\n";
    }
  }
  if (r.contains("written")) s << "  wrote " << r.at("written").get<std::string>() << "\n";
  return s.str();
}

} // namespace glossa::app
