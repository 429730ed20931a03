#pragma once
// Which faces a deformable pair's slave faces may meet (doc/contact.md, "Deformable pairs and
// self-contact"): the master faces within reach of each slave face in the reference
// configuration, fixed for the run because the matrix graph is built once from them, and the
// search of a slave point among its candidates in the current configuration. Eigen and the mesh
// only.
//
// Self-contact is a pair of a face set with itself: a face is never its own candidate, nor is a
// face that shares a node with it (their points meet at the shared node at zero gap, which is
// no contact), and a point only meets a face whose normal opposes its own face's.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "contact/PairContact.hpp"
#include "mesh/HexMesh.hpp"

namespace glossa::contact {

// Where a slave face's contact points sit: an n x n Gauss rule, or cells cut by its candidate
// master faces' edges in the reference configuration (contact/SlaveSegments).
enum class SlaveRule { gauss, segments };

struct DeformablePair {
  std::vector<mesh::ElementFace> masterFaces;  // the slave faces themselves for self-contact
  bool self = false;
  double margin = 0;  // [m]: how much farther than the search radius candidates reach
  // Per slave face (the contact's `faces`, same index): the indices in masterFaces of the faces
  // whose reference bounding boxes lie within search radius + margin of its own.
  std::vector<std::vector<std::uint32_t>> candidates;
  // Per slave face, its contact points, as many on every face (the state keeps a multiplier per
  // point): a face with fewer segmented points is padded with points of weight 0, which carry
  // nothing.
  std::vector<std::vector<SlavePoint>> points;
  std::size_t pointsPerFace() const { return points.empty() ? 0 : points.front().size(); }
};

// The pair's candidates and points, from the reference positions (`pointsPerDirection` for the
// Gauss rule). Refuses (std::invalid_argument) a slave face set that shares a face with the master
// set unless `self`.
DeformablePair pairFaces(const mesh::HexMesh &mesh, const std::vector<mesh::ElementFace> &slaveFaces,
                         std::vector<mesh::ElementFace> masterFaces, bool self, double searchRadius,
                         double margin, SlaveRule rule, int pointsPerDirection);

// A face's four nodes, in its outward right-hand order, and their reference positions.
std::array<mesh::NodeId, 4> faceNodeIds(const mesh::HexMesh &mesh, const mesh::ElementFace &face);
loads::FaceNodes referenceNodes(const mesh::HexMesh &mesh, const mesh::ElementFace &face);

// The nodes a slave face couples in the tangent: its own and its candidates' (sorted, unique).
std::vector<mesh::NodeId> coupledNodes(const mesh::HexMesh &mesh,
                                       const std::vector<mesh::ElementFace> &slaveFaces,
                                       const DeformablePair &pair, std::size_t slaveFace);

// The master face a slave point at x (on a slave face of unit normal `slaveNormal`) meets: among
// `candidates`, the faces (current nodes from `masterAt`) its projection lands inside, within
// the search radius on either side and facing it (normals opposed), the one with the smallest
// |gap|; nothing if none.
struct PairMatch {
  std::uint32_t master = 0;  // index in masterFaces
  FaceProjection projection;
};
std::optional<PairMatch> closestMasterFace(const Eigen::Vector3d &x, const Eigen::Vector3d &slaveNormal,
                                           const std::vector<std::uint32_t> &candidates,
                                           const std::function<loads::FaceNodes(std::uint32_t)> &masterAt,
                                           double searchRadius);

}  // namespace glossa::contact
