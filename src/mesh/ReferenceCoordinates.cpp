#include "mesh/ReferenceCoordinates.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/output/OutputError.hpp"
#include "mesh/MeshError.hpp"

namespace glossa::mesh {

std::vector<Eigen::Vector3d> readReferenceCoordinates(const std::string &path, std::size_t numNodes) {
  std::ifstream in(path);
  if (!in) throw MeshError(path + ": cannot open the reference coordinates file");
  std::vector<Eigen::Vector3d> nodes(numNodes);
  std::vector<int> seenOnLine(numNodes, 0);
  std::string line;
  int lineNumber = 0;
  std::size_t count = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    const std::string where = path + ":" + std::to_string(lineNumber) + ": ";
    for (char &c : line)
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    const std::size_t first = line.find_first_not_of(' ');
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream s(line);
    std::string fields[4], extra;
    for (auto &f : fields)
      if (!(s >> f))
        throw MeshError(where + "expected 'node x y z', got '" + line.substr(first) + "'");
    if (s >> extra)
      throw MeshError(where + "expected 'node x y z', got a fifth field '" + extra + "'");
    long long node = -1;
    try {
      std::size_t used = 0;
      node = std::stoll(fields[0], &used);
      if (used != fields[0].size()) throw std::invalid_argument(fields[0]);
    } catch (const std::exception &) {
      throw MeshError(where + "the node index '" + fields[0] + "' is not an integer");
    }
    if (node < 0 || static_cast<std::size_t>(node) >= numNodes)
      throw MeshError(where + "node " + fields[0] + " is outside the mesh (0 to " +
                               std::to_string(numNodes - 1) + ")");
    if (seenOnLine[node])
      throw MeshError(where + "node " + fields[0] + " is given twice (first on line " +
                               std::to_string(seenOnLine[node]) + ")");
    Eigen::Vector3d x;
    for (int c = 0; c < 3; ++c) {
      try {
        std::size_t used = 0;
        x(c) = std::stod(fields[c + 1], &used);
        if (used != fields[c + 1].size() || !std::isfinite(x(c))) throw std::invalid_argument(fields[c + 1]);
      } catch (const std::exception &) {
        throw MeshError(where + "coordinate '" + fields[c + 1] + "' is not a finite number");
      }
    }
    nodes[node] = x;
    seenOnLine[node] = lineNumber;
    ++count;
  }
  if (count != numNodes)
    throw MeshError(path + ": " + std::to_string(count) + " nodes, but the mesh has " +
                             std::to_string(numNodes) + " (every node exactly once)");
  return nodes;
}

std::size_t countReferenceCoordinates(const std::string &path) {
  std::ifstream in(path);
  if (!in) throw MeshError(path + ": cannot open the reference coordinates file");
  std::size_t count = 0;
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t first = line.find_first_not_of(" \t\r,");
    if (first != std::string::npos && line[first] != '#') ++count;
  }
  return count;
}

void writeReferenceCoordinates(const std::string &path, const std::vector<Eigen::Vector3d> &nodes,
                               const std::vector<std::string> &header) {
  std::FILE *f = std::fopen(path.c_str(), "w");
  if (!f) throw io::OutputError(path + ": cannot write the reference coordinates file");
  for (const auto &h : header) std::fprintf(f, "# %s\n", h.c_str());
  std::fprintf(f, "# node x y z (node: 0-based index in the mesh as the deck builds it; metres)\n");
  for (std::size_t n = 0; n < nodes.size(); ++n)
    std::fprintf(f, "%zu %.17g %.17g %.17g\n", n, nodes[n].x(), nodes[n].y(), nodes[n].z());
  if (std::fclose(f) != 0) throw io::OutputError(path + ": error writing the reference coordinates file");
}

void replaceReferenceNodes(HexMesh &m, std::vector<Eigen::Vector3d> reference) {
  if (reference.size() != m.numNodes())
    throw std::invalid_argument("replaceReferenceNodes: " + std::to_string(reference.size()) + " positions for " +
                                std::to_string(m.numNodes()) + " nodes");
  if (m.imagedNodes.empty()) m.imagedNodes = m.nodes;
  m.nodes = std::move(reference);
  for (auto &[name, point] : m.namedPoints) {
    if (!point.probe()) {
      point.position = m.nodes[point.node];
      continue;
    }
    point.position.setZero();
    for (const auto &[n, w] : point.weights) point.position += w * m.nodes[n];
  }
}

}  // namespace glossa::mesh
