#pragma once
// A hexahedral mesh with named sets: the data model every generator and importer fills.
// No Trilinos here (doc/developing.md): the mesh is replicated on every rank and the assembly
// layer decides which rank owns which element.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace glossa::mesh {

using NodeId = std::int64_t;
using ElementId = std::int64_t;

// Local node numbering of a hexahedron follows the VTK/XDMF convention: nodes 0-3 are the
// bottom face (zeta=-1), counter-clockwise seen from +zeta (from inside the element), 4-7 the
// top face in the same order, so that a right-handed element has a positive Jacobian.
// Reference coordinates of node a: xi = (-1,+1,+1,-1,-1,+1,+1,-1)[a],
// eta = (-1,-1,+1,+1,-1,-1,+1,+1)[a], zeta = (-1,-1,-1,-1,+1,+1,+1,+1)[a].
using Hex = std::array<NodeId, 8>;

// One face of one element: local face index 0..5 in the order
// 0: zeta=-1 (0,3,2,1), 1: zeta=+1 (4,5,6,7), 2: eta=-1 (0,1,5,4),
// 3: xi=+1 (1,2,6,5), 4: eta=+1 (2,3,7,6), 5: xi=-1 (3,0,4,7)
// (node lists ordered so the right-hand normal points out of the element).
struct ElementFace {
  ElementId element;
  int localFace;
  bool operator==(const ElementFace &o) const {
    return element == o.element && localFace == o.localFace;
  }
  // Sets are kept sorted by (element, localFace) so that they compare and merge cheaply.
  bool operator<(const ElementFace &o) const {
    return element < o.element || (element == o.element && localFace < o.localFace);
  }
};

// The four local node indices of each local face, outward right-hand ordering.
extern const std::array<std::array<int, 4>, 6> kHexFaceNodes;

// A named point for output (traces) and control: a location in the reference configuration
// and the mesh node it sits on (generators put named points on nodes), or a probe inside an
// element, whose values are its element's nodal values interpolated at it.
struct NamedPoint {
  Eigen::Vector3d position;
  NodeId node; // the node it is at; a probe: the nearest node of its element
  // A probe: its element's nodes and their trilinear shape functions at the point (summing to 1);
  // empty for a point at a node.
  std::vector<std::pair<NodeId, double>> weights;
  bool probe() const { return !weights.empty(); }
  // sum_a N_a v(a) of a per-node vector field v (3 per node, by mesh node).
  Eigen::Vector3d interpolate(const std::vector<double> &v) const {
    if (!probe()) return {v[3 * node], v[3 * node + 1], v[3 * node + 2]};
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (const auto &[n, w] : weights) x += w * Eigen::Vector3d(v[3 * n], v[3 * n + 1], v[3 * n + 2]);
    return x;
  }
};

struct HexMesh {
  std::vector<Eigen::Vector3d> nodes;  // reference coordinates [m]
  std::vector<Hex> elements;
  std::map<std::string, std::vector<NodeId>> nodeSets;        // sorted, unique
  std::map<std::string, std::vector<ElementFace>> faceSets;   // boundary faces
  std::map<std::string, std::vector<ElementId>> elementSets;  // sorted, unique
  std::map<std::string, NamedPoint> namedPoints;
  // Fibre polylines by muscle (e.g. the tongue's Fibers.mac): reference positions of each
  // polyline's vertices, in the file's order. Geometric, so refinement copies them unchanged.
  std::map<std::string, std::vector<std::vector<Eigen::Vector3d>>> fibrePolylines;
  // The node positions as imaged (as read), kept when a zero-strain configuration replaced them
  // (Mesh/reference coordinates file, §8.1); empty when `nodes` are the imaged positions. They
  // are the goals of the controlled runs and what traces.csv measures the dx, dy, dz from.
  std::vector<Eigen::Vector3d> imagedNodes;

  std::size_t numNodes() const { return nodes.size(); }
  // Where node n is in the imaged geometry: imagedNodes[n], or nodes[n] when there is no other.
  const Eigen::Vector3d &imagedPosition(NodeId n) const { return imagedNodes.empty() ? nodes.at(n) : imagedNodes.at(n); }
  std::size_t numElements() const { return elements.size(); }

  // Node coordinates of one element as the 8x3 matrix the element kernels take.
  // Throws std::out_of_range for an element id outside [0, numElements()).
  Eigen::Matrix<double, 8, 3> elementCoordinates(ElementId e) const;

  // Nodes touched by the faces of a face set (sorted, unique).
  std::vector<NodeId> nodesOfFaceSet(const std::string &name) const;

  // Throws std::runtime_error naming the set and the known sets if absent.
  const std::vector<NodeId> &nodeSet(const std::string &name) const;
  const std::vector<ElementFace> &faceSet(const std::string &name) const;

  // Node id nearest to a point (ties: lowest id). Throws std::runtime_error on an empty mesh.
  NodeId nearestNode(const Eigen::Vector3d &x) const;
};

// Axis-aligned bounding box of all nodes, as (lower corner, upper corner).
std::pair<Eigen::Vector3d, Eigen::Vector3d> boundingBox(const HexMesh &mesh);

// The length scale that geometric tolerances are relative to: the bounding-box diagonal.
double meshSize(const HexMesh &mesh);

// Mean of the four corner nodes of an element face.
Eigen::Vector3d faceCentroid(const HexMesh &mesh, ElementFace face);

// Faces that belong to exactly one element, sorted by (element, localFace). This is the
// natural `from` list for facesInBox when a deck selects a boundary region by a box.
std::vector<ElementFace> boundaryFaces(const HexMesh &mesh);

// Faces of `from` whose centroid lies in the closed box [lo, hi], widened by 1e-9 * meshSize
// so that a flat box (lo.x == hi.x) picks the faces lying in that plane. Keeps `from`'s order.
std::vector<ElementFace> facesInBox(const HexMesh &mesh, const std::vector<ElementFace> &from,
                                    const Eigen::Vector3d &lo, const Eigen::Vector3d &hi);

// Unit outward normal of an element face in the reference configuration (the area-weighted
// normal of the bilinear face, (x2 - x0) x (x3 - x1) normalised).
Eigen::Vector3d faceOutwardNormal(const HexMesh &mesh, ElementFace face);

// Faces of `from` whose reference outward unit normal n satisfies n . d >= minCosine, d the
// normalised `direction` (a boundary region selected by the way it faces). Keeps `from`'s order.
// Throws std::invalid_argument for a zero direction.
std::vector<ElementFace> facesFacing(const HexMesh &mesh, const std::vector<ElementFace> &from,
                                     const Eigen::Vector3d &direction, double minCosine);

// Nodes in the closed box [lo, hi] with the same tolerance as facesInBox (sorted).
std::vector<NodeId> nodesInBox(const HexMesh &mesh, const Eigen::Vector3d &lo,
                               const Eigen::Vector3d &hi);

}  // namespace glossa::mesh
