#include "mesh/StructuredHexGrid.hpp"

#include <algorithm>
#include <stdexcept>

namespace glossa::mesh {

HexMesh structuredHexGrid(const std::array<int, 3> &cells,
                          const std::function<Eigen::Vector3d(int, int, int)> &position,
                          const BlockSideNames &sideNames) {
  for (int d = 0; d < 3; ++d) {
    if (cells[d] < 1) {
      throw std::invalid_argument("structuredHexGrid: cells[" + std::to_string(d) +
                                  "] must be >= 1, got " + std::to_string(cells[d]));
    }
  }
  const NodeId nx = cells[0], ny = cells[1], nz = cells[2];
  auto nodeId = [&](NodeId i, NodeId j, NodeId k) { return i + (nx + 1) * (j + (ny + 1) * k); };

  HexMesh mesh;
  mesh.nodes.resize(static_cast<std::size_t>((nx + 1) * (ny + 1) * (nz + 1)));
  for (NodeId k = 0; k <= nz; ++k) {
    for (NodeId j = 0; j <= ny; ++j) {
      for (NodeId i = 0; i <= nx; ++i) {
        mesh.nodes[static_cast<std::size_t>(nodeId(i, j, k))] =
            position(static_cast<int>(i), static_cast<int>(j), static_cast<int>(k));
      }
    }
  }

  // Local face of the element on each side, in sideNames order (see kHexFaceNodes):
  // i = 0 is xi = -1 (face 5), i = nx is xi = +1 (3), j = 0 / ny are eta = -1 / +1 (2 / 4),
  // k = 0 / nz are zeta = -1 / +1 (0 / 1).
  constexpr std::array<int, 6> kSideLocalFace = {5, 3, 2, 4, 0, 1};
  std::array<std::vector<ElementFace>, 6> sides;

  mesh.elements.reserve(static_cast<std::size_t>(nx * ny * nz));
  for (NodeId k = 0; k < nz; ++k) {
    for (NodeId j = 0; j < ny; ++j) {
      for (NodeId i = 0; i < nx; ++i) {
        const ElementId e = static_cast<ElementId>(mesh.elements.size());
        mesh.elements.push_back({nodeId(i, j, k), nodeId(i + 1, j, k), nodeId(i + 1, j + 1, k),
                                 nodeId(i, j + 1, k), nodeId(i, j, k + 1), nodeId(i + 1, j, k + 1),
                                 nodeId(i + 1, j + 1, k + 1), nodeId(i, j + 1, k + 1)});
        const std::array<bool, 6> onSide = {i == 0,      i == nx - 1, j == 0,
                                            j == ny - 1, k == 0,      k == nz - 1};
        for (int s = 0; s < 6; ++s) {
          if (onSide[s]) sides[s].push_back({e, kSideLocalFace[s]});
        }
      }
    }
  }

  for (int s = 0; s < 6; ++s) {
    // Elements are visited in increasing id, so each side's face list is already sorted.
    mesh.faceSets[sideNames[s]] = std::move(sides[s]);
    mesh.nodeSets[sideNames[s]] = mesh.nodesOfFaceSet(sideNames[s]);
  }

  std::vector<ElementId> all(mesh.elements.size());
  for (std::size_t e = 0; e < all.size(); ++e) all[e] = static_cast<ElementId>(e);
  mesh.elementSets["all"] = std::move(all);
  return mesh;
}

}  // namespace glossa::mesh
