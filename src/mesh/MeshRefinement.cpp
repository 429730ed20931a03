#include "mesh/MeshRefinement.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace glossa::mesh {

namespace {

// Reference coordinates of the local nodes (HexMesh.hpp), as 0/1 instead of -1/+1.
constexpr int kI[8] = {0, 1, 1, 0, 0, 1, 1, 0};
constexpr int kJ[8] = {0, 0, 1, 1, 0, 0, 1, 1};
constexpr int kK[8] = {0, 0, 0, 0, 1, 1, 1, 1};

// For local face f, the child index that touches it: which axis (0 = i, 1 = j, 2 = k) and value.
constexpr int kFaceAxis[6] = {2, 2, 1, 0, 1, 0};
constexpr int kFaceSide[6] = {0, 1, 0, 1, 1, 0};

HexMesh refineOnce(const HexMesh &mesh) {
  HexMesh fine;
  fine.nodes = mesh.nodes;
  std::map<std::vector<NodeId>, NodeId> created;  // sorted parent nodes -> new node
  // The node at lattice point (a, b, c) in {0,1,2}^3 of an element: the mean of the parent
  // corners the point is "between" (one corner, an edge's two, a face's four, all eight).
  auto latticeNode = [&](const Hex &hex, int a, int b, int c) -> NodeId {
    std::vector<NodeId> parents;
    for (int n = 0; n < 8; ++n) {
      if ((a == 1 || a == 2 * kI[n]) && (b == 1 || b == 2 * kJ[n]) && (c == 1 || c == 2 * kK[n])) {
        parents.push_back(hex[n]);
      }
    }
    if (parents.size() == 1) return parents.front();
    std::sort(parents.begin(), parents.end());
    const auto it = created.find(parents);
    if (it != created.end()) return it->second;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (NodeId p : parents) x += mesh.nodes[static_cast<std::size_t>(p)];
    fine.nodes.push_back(x / static_cast<double>(parents.size()));
    const NodeId id = static_cast<NodeId>(fine.nodes.size() - 1);
    created.emplace(std::move(parents), id);
    return id;
  };

  fine.elements.reserve(8 * mesh.elements.size());
  for (const Hex &hex : mesh.elements) {
    NodeId lattice[3][3][3];
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        for (int c = 0; c < 3; ++c) lattice[a][b][c] = latticeNode(hex, a, b, c);
      }
    }
    for (int child = 0; child < 8; ++child) {
      const int i = child & 1, j = (child >> 1) & 1, k = (child >> 2) & 1;
      Hex h;
      for (int n = 0; n < 8; ++n) h[n] = lattice[i + kI[n]][j + kJ[n]][k + kK[n]];
      fine.elements.push_back(h);
    }
  }

  for (const auto &[name, set] : mesh.elementSets) {
    auto &children = fine.elementSets[name];
    for (ElementId e : set) {
      for (int c = 0; c < 8; ++c) children.push_back(8 * e + c);
    }
  }
  for (const auto &[name, set] : mesh.faceSets) {
    auto &children = fine.faceSets[name];
    for (const ElementFace &f : set) {
      for (int c = 0; c < 8; ++c) {
        const int index[3] = {c & 1, (c >> 1) & 1, (c >> 2) & 1};
        if (index[kFaceAxis[f.localFace]] == kFaceSide[f.localFace])
          children.push_back({8 * f.element + c, f.localFace});
      }
    }
    std::sort(children.begin(), children.end());
  }
  for (const auto &[name, set] : mesh.nodeSets) {
    auto &nodes = fine.nodeSets[name];
    nodes = set;
    for (const auto &[parents, id] : created) {
      const bool inside = std::all_of(parents.begin(), parents.end(), [&set](NodeId p) {
        return std::binary_search(set.begin(), set.end(), p);
      });
      if (inside) nodes.push_back(id);
    }
    std::sort(nodes.begin(), nodes.end());
  }
  fine.namedPoints = mesh.namedPoints;
  fine.fibrePolylines = mesh.fibrePolylines;
  return fine;
}

}  // namespace

HexMesh refineUniformly(const HexMesh &mesh, int levels) {
  if (levels < 0)
    throw std::invalid_argument("refineUniformly: levels must be >= 0, got " + std::to_string(levels));
  HexMesh result = mesh;
  for (int level = 0; level < levels; ++level) result = refineOnce(result);
  return result;
}

std::vector<Eigen::Vector3d> refinedPositions(const HexMesh &mesh, std::vector<Eigen::Vector3d> positions,
                                              int levels) {
  if (positions.size() != mesh.numNodes())
    throw std::invalid_argument("refinedPositions: " + std::to_string(positions.size()) + " positions for " +
                                std::to_string(mesh.numNodes()) + " nodes");
  HexMesh moved;
  moved.nodes = std::move(positions);
  moved.elements = mesh.elements;  // the sets do not move a node: only the connectivity is needed
  return refineUniformly(moved, levels).nodes;
}

}  // namespace glossa::mesh
