#pragma once
// What the scene says of the airway's lumen (doc/airway.md): the lumen's sections between the
// tongue's airway faces and the wall, the mesh nodes whose positions are the tongue surface's
// vertices, and the contact whose area airway.csv reports beside the sections.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "airway/AirwayLumen.hpp"
#include "mesh/HexMesh.hpp"

namespace glossa::model {

struct AirwayOutput {
  std::shared_ptr<const airway::AirwayLumen> lumen;
  std::vector<mesh::NodeId> nodes;  // the lumen's tongue vertex k is node nodes[k]
  int contact = -1;                 // index into Scene::contacts; -1: none reported
  // The closing-pressure search (doc/airway.md, "Pcrit"): the follower pressure whose suction is
  // raised until the airway closes (index into Scene::pressures; -1: no search), and how closely
  // the closing pressure is bracketed [Pa].
  int pressureLoad = -1;
  double pressureTolerance = 9.80665;

  // The tongue vertices' current positions from every node's displacement (3 per node).
  std::vector<Eigen::Vector3d> positions(const mesh::HexMesh &mesh, const std::vector<double> &u) const {
    std::vector<Eigen::Vector3d> x;
    x.reserve(nodes.size());
    for (mesh::NodeId n : nodes) {
      const auto k = static_cast<std::size_t>(n);
      x.push_back(mesh.nodes[k] + Eigen::Vector3d(u[3 * k], u[3 * k + 1], u[3 * k + 2]));
    }
    return x;
  }
  // The lumen at every node's displacement `u` (3 per node).
  airway::LumenState measure(const mesh::HexMesh &mesh, const std::vector<double> &u) const {
    return lumen->measure(positions(mesh, u));
  }
};

}  // namespace glossa::model
