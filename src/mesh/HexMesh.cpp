#include "mesh/HexMesh.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace glossa::mesh {

const std::array<std::array<int, 4>, 6> kHexFaceNodes = {{
    {0, 3, 2, 1},  // zeta = -1
    {4, 5, 6, 7},  // zeta = +1
    {0, 1, 5, 4},  // eta = -1
    {1, 2, 6, 5},  // xi = +1
    {2, 3, 7, 6},  // eta = +1
    {3, 0, 4, 7},  // xi = -1
}};

namespace {

// "known node sets: a, b, c" (or "none") for error messages: a typo in a deck should show
// the user what the mesh actually offers.
template <typename Map>
std::string knownNames(const Map &sets) {
  if (sets.empty()) return "none";
  std::ostringstream out;
  bool first = true;
  for (const auto &entry : sets) {
    out << (first ? "" : ", ") << entry.first;
    first = false;
  }
  return out.str();
}

template <typename Map>
const typename Map::mapped_type &findSet(const Map &sets, const std::string &name,
                                         const char *kind) {
  const auto it = sets.find(name);
  if (it == sets.end()) {
    throw std::runtime_error("unknown " + std::string(kind) + " '" + name + "'; known " + kind +
                             "s: " + knownNames(sets));
  }
  return it->second;
}

// Closed-box test widened by tol in every direction.
bool inBox(const Eigen::Vector3d &x, const Eigen::Vector3d &lo, const Eigen::Vector3d &hi,
           double tol) {
  return (x.array() >= lo.array() - tol).all() && (x.array() <= hi.array() + tol).all();
}

constexpr double kRelativeBoxTolerance = 1e-9;

}  // namespace

Eigen::Matrix<double, 8, 3> HexMesh::elementCoordinates(ElementId e) const {
  if (e < 0 || static_cast<std::size_t>(e) >= elements.size()) {
    throw std::out_of_range("element id " + std::to_string(e) + " outside [0, " +
                            std::to_string(elements.size()) + ")");
  }
  Eigen::Matrix<double, 8, 3> X;
  const Hex &hex = elements[static_cast<std::size_t>(e)];
  for (int a = 0; a < 8; ++a) X.row(a) = nodes[static_cast<std::size_t>(hex[a])].transpose();
  return X;
}

std::vector<NodeId> HexMesh::nodesOfFaceSet(const std::string &name) const {
  std::vector<NodeId> result;
  for (const ElementFace &f : faceSet(name)) {
    const Hex &hex = elements.at(static_cast<std::size_t>(f.element));
    for (int a : kHexFaceNodes.at(static_cast<std::size_t>(f.localFace))) {
      result.push_back(hex[a]);
    }
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

const std::vector<NodeId> &HexMesh::nodeSet(const std::string &name) const {
  return findSet(nodeSets, name, "node set");
}

const std::vector<ElementFace> &HexMesh::faceSet(const std::string &name) const {
  return findSet(faceSets, name, "face set");
}

NodeId HexMesh::nearestNode(const Eigen::Vector3d &x) const {
  if (nodes.empty()) throw std::runtime_error("nearestNode: the mesh has no nodes");
  NodeId best = 0;
  double bestDistance2 = std::numeric_limits<double>::infinity();
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const double d2 = (nodes[n] - x).squaredNorm();
    if (d2 < bestDistance2) {  // strict: the lowest id wins a tie
      bestDistance2 = d2;
      best = static_cast<NodeId>(n);
    }
  }
  return best;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> boundingBox(const HexMesh &mesh) {
  if (mesh.nodes.empty()) return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  Eigen::Vector3d lo = mesh.nodes.front();
  Eigen::Vector3d hi = lo;
  for (const Eigen::Vector3d &x : mesh.nodes) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return {lo, hi};
}

double meshSize(const HexMesh &mesh) {
  const auto [lo, hi] = boundingBox(mesh);
  return (hi - lo).norm();
}

Eigen::Vector3d faceCentroid(const HexMesh &mesh, ElementFace face) {
  const Hex &hex = mesh.elements.at(static_cast<std::size_t>(face.element));
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int a : kHexFaceNodes.at(static_cast<std::size_t>(face.localFace))) {
    sum += mesh.nodes[static_cast<std::size_t>(hex[a])];
  }
  return 0.25 * sum;
}

std::vector<ElementFace> boundaryFaces(const HexMesh &mesh) {
  // A face is interior iff another element has a face with the same four nodes; the sorted
  // node quadruple is orientation-free, so a conforming neighbour produces the same key.
  using Keyed = std::pair<std::array<NodeId, 4>, ElementFace>;
  std::vector<Keyed> faces;
  faces.reserve(6 * mesh.elements.size());
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    for (int f = 0; f < 6; ++f) {
      std::array<NodeId, 4> key;
      for (int a = 0; a < 4; ++a) key[a] = mesh.elements[e][kHexFaceNodes[f][a]];
      std::sort(key.begin(), key.end());
      faces.push_back({key, {static_cast<ElementId>(e), f}});
    }
  }
  std::sort(faces.begin(), faces.end());
  std::vector<ElementFace> result;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].first == faces[i].first) ++j;
    if (j - i == 1) result.push_back(faces[i].second);
    i = j;
  }
  std::sort(result.begin(), result.end());
  return result;
}

std::vector<ElementFace> facesInBox(const HexMesh &mesh, const std::vector<ElementFace> &from,
                                    const Eigen::Vector3d &lo, const Eigen::Vector3d &hi) {
  const double tol = kRelativeBoxTolerance * meshSize(mesh);
  std::vector<ElementFace> result;
  for (const ElementFace &f : from) {
    if (inBox(faceCentroid(mesh, f), lo, hi, tol)) result.push_back(f);
  }
  return result;
}

Eigen::Vector3d faceOutwardNormal(const HexMesh &mesh, ElementFace face) {
  const auto &hex = mesh.elements.at(static_cast<std::size_t>(face.element));
  const auto &local = kHexFaceNodes.at(static_cast<std::size_t>(face.localFace));
  const Eigen::Vector3d &x0 = mesh.nodes[hex[local[0]]], &x1 = mesh.nodes[hex[local[1]]];
  const Eigen::Vector3d &x2 = mesh.nodes[hex[local[2]]], &x3 = mesh.nodes[hex[local[3]]];
  return (x2 - x0).cross(x3 - x1).normalized();
}

std::vector<ElementFace> facesFacing(const HexMesh &mesh, const std::vector<ElementFace> &from,
                                     const Eigen::Vector3d &direction, double minCosine) {
  if (!(direction.norm() > 0.0)) throw std::invalid_argument("facesFacing: the direction is zero");
  const Eigen::Vector3d d = direction.normalized();
  std::vector<ElementFace> result;
  for (const ElementFace &f : from)
    if (faceOutwardNormal(mesh, f).dot(d) >= minCosine) result.push_back(f);
  return result;
}

std::vector<NodeId> nodesInBox(const HexMesh &mesh, const Eigen::Vector3d &lo,
                               const Eigen::Vector3d &hi) {
  const double tol = kRelativeBoxTolerance * meshSize(mesh);
  std::vector<NodeId> result;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    if (inBox(mesh.nodes[n], lo, hi, tol)) result.push_back(static_cast<NodeId>(n));
  }
  return result;
}

}  // namespace glossa::mesh
