#pragma once
// Two boxes in one mesh, one above the other and not joined, for the deformable-pair tests: the
// lower one's top is the face set "lower top", the upper one's bottom "upper bottom"; the lower
// one keeps the generator's sets (zmin: its bottom).

#include <array>

#include "mesh/BoxGenerator.hpp"

namespace glossa::test {

// Boxes of side `side` and height `side` with the given cells, the upper `gap` above the lower.
inline mesh::HexMesh stackedBoxes(double side, const std::array<int, 3> &lowerCells,
                                  const std::array<int, 3> &upperCells, double gap) {
  mesh::HexMesh m = mesh::generateBox({0, 0, 0}, {side, side, side}, lowerCells);
  const mesh::HexMesh upper = mesh::generateBox({0, 0, side + gap}, {side, side, side}, upperCells);
  const auto nodeOffset = static_cast<mesh::NodeId>(m.nodes.size());
  const auto elementOffset = static_cast<mesh::ElementId>(m.elements.size());
  m.nodes.insert(m.nodes.end(), upper.nodes.begin(), upper.nodes.end());
  for (auto hex : upper.elements) {
    for (auto &n : hex) n += nodeOffset;
    m.elements.push_back(hex);
  }
  m.faceSets["lower top"] = m.faceSets.at("zmax");
  for (auto f : upper.faceSets.at("zmin")) {
    f.element += elementOffset;
    m.faceSets["upper bottom"].push_back(f);
  }
  return m;
}

}  // namespace glossa::test
