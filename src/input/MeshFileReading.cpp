#include "input/MeshFileReading.hpp"

#include <filesystem>
#include <map>
#include <stdexcept>

#include "input/DeckPaths.hpp"
#include "input/DeckVector.hpp"
#include "io/deck/DeckError.hpp"
#include "mesh/AnsysReader.hpp"
#include "mesh/MeshFile.hpp"
#include "mesh/MovedNodes.hpp"

namespace glossa::input {

namespace {
using Teuchos::Array;
using Teuchos::ParameterList;

// The ANSYS fibre polylines (Mesh/File/ANSYS fibres), numbered by the components' muscle names.
void readFibres(const io::Deck &deck, const mesh::AnsysComponents &components, mesh::ImportedMesh &imported) {
  const ParameterList &f = deck.root().sublist("Mesh").sublist("File");
  if (f.get<std::string>("ANSYS fibres").empty()) return;
  if (f.get<std::string>("ANSYS components").empty())
    throw io::DeckError(deck.where({"Mesh", "File", "ANSYS fibres"}) +
                        ": the fibre macro numbers its muscles by the components' muscleName array; "
                        "give 'ANSYS components' too");
  std::map<std::int64_t, Eigen::Vector3d> anchors;
  const auto &points = f.sublist("ANSYS fibre anchors");
  for (auto it = points.begin(); it != points.end(); ++it) {
    const auto &a = points.sublist(points.name(it));
    anchors[a.get<int>("id")] = vec3(a.get<Array<double>>("position"));
  }
  const auto &names = components.declaredNames.empty() ? components.names : components.declaredNames;
  try {
    for (auto &muscle :
         mesh::readAnsysFibres(relativeToDeck(deck, f.get<std::string>("ANSYS fibres")), imported, names, anchors)) {
      auto &lines = imported.mesh.fibrePolylines[muscle.muscle];
      for (const auto &fibre : muscle.fibres) {
        lines.emplace_back();
        for (const auto &vertex : fibre) lines.back().push_back(vertex.position);
      }
    }
  } catch (const std::runtime_error &e) {
    throw io::DeckError(deck.where({"Mesh", "File", "ANSYS fibres"}) + ": " + e.what());
  }
}

}  // namespace

mesh::HexMesh readFileMesh(const io::Deck &deck, std::vector<std::string> &notes) {
  const ParameterList &f = deck.root().sublist("Mesh").sublist("File");
  auto resolve = [&deck](const std::string &path) { return relativeToDeck(deck, path); };
  if (f.get<std::string>("path").empty())
    throw io::DeckError(deck.where({"Mesh", "File", "path"}) + " is empty: name the mesh file");
  try {
    mesh::ImportedMesh imported = mesh::readMeshFile(resolve(f.get<std::string>("path")), f.get<std::string>("format"));
    if (!f.get<std::string>("moved nodes").empty()) {
      try {
        mesh::moveNodes(resolve(f.get<std::string>("moved nodes")), imported);
      } catch (const std::runtime_error &e) {
        throw io::DeckError(deck.where({"Mesh", "File", "moved nodes"}) + ": " + e.what());
      }
    }
    mesh::AnsysComponents components;
    if (!f.get<std::string>("ANSYS components").empty())
      components = mesh::readAnsysComponents(resolve(f.get<std::string>("ANSYS components")), imported);
    readFibres(deck, components, imported);
    const auto &lists = f.sublist("Node lists");
    for (auto it = lists.begin(); it != lists.end(); ++it)
      mesh::readAnsysNodeList(resolve(lists.sublist(lists.name(it)).get<std::string>("file")), lists.name(it), imported);
    notes = std::move(imported.notes);
    return std::move(imported.mesh);
  } catch (const io::DeckError &) {
    throw;
  } catch (const std::runtime_error &e) {
    throw io::DeckError(deck.where({"Mesh", "File", "path"}) + ": " + e.what());
  }
}

}  // namespace glossa::input
