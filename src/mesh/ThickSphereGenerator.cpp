#include "mesh/ThickSphereGenerator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

#include "mesh/StructuredHexGrid.hpp"

namespace glossa::mesh {

namespace {

// A node by its integer address: the point (I, J, K) / n of the unit cube's surface (one of
// them equal to n) and its radial layer. Patches meet on the cube's edges, where the addresses
// coincide, so shared nodes merge exactly.
using NodeAddress = std::array<int, 4>;

// Patch d is the cube face where coordinate d equals 1; its grid (i, j) runs along the two other
// coordinates in the cyclic order (d+1, d+2), so (i, j, radial) is right-handed for every patch.
NodeAddress address(int patch, int i, int j, int layer, int n) {
  NodeAddress a{};
  a[patch] = n;
  a[(patch + 1) % 3] = i;
  a[(patch + 2) % 3] = j;
  a[3] = layer;
  return a;
}

Eigen::Vector3d position(const NodeAddress &a, int n, double radius) {
  // Equal angles on each cube face: tan(pi/4 I/n), exactly 0 on the symmetry planes.
  Eigen::Vector3d c;
  for (int d = 0; d < 3; ++d) c(d) = a[d] == n ? 1.0 : std::tan(0.25 * M_PI * a[d] / n);
  return radius * c.normalized();
}

} // namespace

HexMesh generateThickSphere(double innerRadius, double outerRadius, int radialCells, int cellsPerPatchSide) {
  if (!(innerRadius > 0.0) || !(outerRadius > innerRadius) || !std::isfinite(outerRadius))
    throw std::invalid_argument("generateThickSphere: need 0 < inner radius < outer radius (finite)");
  if (radialCells < 1 || cellsPerPatchSide < 1)
    throw std::invalid_argument("generateThickSphere: cell counts must be >= 1");
  const int n = cellsPerPatchSide, m = radialCells;
  const auto radius = [&](int layer) {
    return layer == m ? outerRadius : innerRadius + (outerRadius - innerRadius) * layer / m;
  };
  // The sides of patch d's grid, in the order i = 0, i = n, j = 0, j = n, inner, outer: i = 0 is
  // the plane of coordinate d+1, j = 0 that of d+2; i = n and j = n are shared with the other
  // patches (dropped).
  const std::array<std::string, 3> plane = {"x0", "y0", "z0"};
  HexMesh out;
  std::map<NodeAddress, NodeId> merged;
  for (int patch = 0; patch < 3; ++patch) {
    const HexMesh block = structuredHexGrid(
        {n, n, m}, [&](int i, int j, int k) { return position(address(patch, i, j, k, n), n, radius(k)); },
        {plane[(patch + 1) % 3], "", plane[(patch + 2) % 3], "", "inner", "outer"});
    // Block node id i + (n+1)(j + (n+1)k) -> merged id.
    std::vector<NodeId> global(block.numNodes());
    for (int k = 0; k <= m; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          const auto id = static_cast<std::size_t>(i + (n + 1) * (j + (n + 1) * k));
          const auto [it, fresh] = merged.try_emplace(address(patch, i, j, k, n), out.nodes.size());
          if (fresh) out.nodes.push_back(block.nodes[id]);
          global[id] = it->second;
        }
    const auto elementOffset = static_cast<ElementId>(out.elements.size());
    for (const auto &hex : block.elements) {
      Hex h;
      for (int a = 0; a < 8; ++a) h[a] = global[static_cast<std::size_t>(hex[a])];
      out.elements.push_back(h);
    }
    for (const auto &[name, faces] : block.faceSets) {
      if (name.empty()) continue;
      for (const auto &f : faces) out.faceSets[name].push_back({f.element + elementOffset, f.localFace});
    }
  }
  for (auto &[name, faces] : out.faceSets) {
    std::sort(faces.begin(), faces.end());
    out.nodeSets[name] = out.nodesOfFaceSet(name);
  }
  auto &all = out.elementSets["all"];
  for (std::size_t e = 0; e < out.numElements(); ++e) all.push_back(static_cast<ElementId>(e));
  const NodeId inner = merged.at(address(0, 0, 0, 0, n)), outer = merged.at(address(0, 0, 0, m, n));
  out.namedPoints["inner"] = {out.nodes[static_cast<std::size_t>(inner)], inner, {}};
  out.namedPoints["outer"] = {out.nodes[static_cast<std::size_t>(outer)], outer, {}};
  return out;
}

} // namespace glossa::mesh
