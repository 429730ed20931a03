#include "mesh/MeshChecks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "mesh/MeshQuality.hpp"

namespace glossa::mesh {

namespace {
// The edges of a hexahedron by local node numbers (the ordering of HexShape: 0-3 bottom, 4-7 top).
constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                               {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

int findRoot(std::vector<int> &parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}
} // namespace

MeshCheckReport checkMesh(const HexMesh &mesh, double relativeTolerance) {
  MeshCheckReport report;
  const std::size_t n = mesh.numNodes();
  std::vector<char> used(n, 0);
  double shortestEdge = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    const Hex &hex = mesh.elements[e];
    for (NodeId node : hex) used.at(static_cast<std::size_t>(node)) = 1;
    for (const auto &edge : kEdges) {
      const double length = (mesh.nodes[hex[edge[0]]] - mesh.nodes[hex[edge[1]]]).norm();
      if (length > 0.0) shortestEdge = std::min(shortestEdge, length);
    }
    const double q = scaledJacobian(mesh.elementCoordinates(static_cast<ElementId>(e)));
    if (!(q > 0.0)) report.invertedCorners.push_back({static_cast<ElementId>(e), q});
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!used[i]) report.unusedNodes.push_back(static_cast<NodeId>(i));

  // Coincident nodes: sorted by x, each node is compared with those within the tolerance in x.
  if (std::isfinite(shortestEdge)) {
    const double tolerance = relativeTolerance * shortestEdge;
    std::vector<NodeId> order(n);
    std::iota(order.begin(), order.end(), NodeId{0});
    std::sort(order.begin(), order.end(), [&](NodeId a, NodeId b) { return mesh.nodes[a].x() < mesh.nodes[b].x(); });
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n && mesh.nodes[order[j]].x() - mesh.nodes[order[i]].x() <= tolerance; ++j)
        if ((mesh.nodes[order[j]] - mesh.nodes[order[i]]).norm() <= tolerance)
          report.coincidentNodes.emplace_back(std::min(order[i], order[j]), std::max(order[i], order[j]));
    std::sort(report.coincidentNodes.begin(), report.coincidentNodes.end());
  }

  // Duplicate elements: the same set of eight nodes, in any order.
  std::vector<std::pair<Hex, ElementId>> keyed;
  keyed.reserve(mesh.numElements());
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    Hex key = mesh.elements[e];
    std::sort(key.begin(), key.end());
    keyed.emplace_back(key, static_cast<ElementId>(e));
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t i = 1; i < keyed.size(); ++i)
    if (keyed[i].first == keyed[i - 1].first) {
      std::size_t first = i - 1;
      while (first > 0 && keyed[first - 1].first == keyed[i].first) --first;
      report.duplicateElements.emplace_back(keyed[first].second, keyed[i].second);
    }
  std::sort(report.duplicateElements.begin(), report.duplicateElements.end());
  return report;
}

std::pair<std::vector<int>, int> meshParts(const HexMesh &mesh) {
  const int n = static_cast<int>(mesh.numNodes());
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  for (const Hex &hex : mesh.elements)
    for (int a = 1; a < 8; ++a) {
      const int r0 = findRoot(parent, static_cast<int>(hex[0])), ra = findRoot(parent, static_cast<int>(hex[a]));
      if (r0 != ra) parent[static_cast<std::size_t>(ra)] = r0;
    }
  std::vector<int> partOfRoot(static_cast<std::size_t>(n), -1), partOfElement;
  int parts = 0;
  partOfElement.reserve(mesh.numElements());
  for (const Hex &hex : mesh.elements) {
    int &p = partOfRoot[static_cast<std::size_t>(findRoot(parent, static_cast<int>(hex[0])))];
    if (p < 0) p = parts++;
    partOfElement.push_back(p);
  }
  return {partOfElement, parts};
}

} // namespace glossa::mesh
