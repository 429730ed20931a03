#include "contact/DeformablePair.hpp"

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "contact/SlaveSegments.hpp"

namespace glossa::contact {

namespace {
struct Box {
  Eigen::Vector3d lo, hi;
};
Box boxOf(const mesh::HexMesh &mesh, const mesh::ElementFace &face) {
  Box b{Eigen::Vector3d::Constant(INFINITY), Eigen::Vector3d::Constant(-INFINITY)};
  for (mesh::NodeId n : faceNodeIds(mesh, face)) {
    b.lo = b.lo.cwiseMin(mesh.nodes[n]);
    b.hi = b.hi.cwiseMax(mesh.nodes[n]);
  }
  return b;
}
// The distance between two boxes (0 if they overlap): no point of one face is nearer the other.
double distance(const Box &a, const Box &b) {
  return (a.lo - b.hi).cwiseMax(b.lo - a.hi).cwiseMax(0.0).norm();
}

// The pairs (slave i, master m) whose boxes lie within `reach` of each other, by CGAL's box
// intersection (a sweep over sorted boxes, O(n log n + pairs)): each box grown by reach / 2 on every
// side meets another exactly when their per-axis gaps are all at most reach, a superset of the
// Euclidean test, which then decides. Each slave's list comes out sorted by master index.
std::vector<std::vector<std::uint32_t>> boxesWithinReach(const std::vector<Box> &slave, const std::vector<Box> &master,
                                                         double reach) {
  using CgalBox = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::uint32_t>;
  const auto grown = [&](const std::vector<Box> &boxes) {
    std::vector<CgalBox> out;
    out.reserve(boxes.size());
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      Eigen::Vector3d lo = boxes[k].lo.array() - 0.5 * reach, hi = boxes[k].hi.array() + 0.5 * reach;
      out.emplace_back(lo.data(), hi.data(), static_cast<std::uint32_t>(k));
    }
    return out;
  };
  std::vector<CgalBox> s = grown(slave), m = grown(master);
  std::vector<std::vector<std::uint32_t>> within(slave.size());
  CGAL::box_intersection_d(s.begin(), s.end(), m.begin(), m.end(), [&](const CgalBox &a, const CgalBox &b) {
    if (distance(slave[a.info()], master[b.info()]) <= reach) within[a.info()].push_back(b.info());
  });
  for (auto &list : within) std::sort(list.begin(), list.end());
  return within;
}
}  // namespace

std::array<mesh::NodeId, 4> faceNodeIds(const mesh::HexMesh &mesh, const mesh::ElementFace &face) {
  std::array<mesh::NodeId, 4> nodes{};
  for (int k = 0; k < 4; ++k) nodes[k] = mesh.elements[face.element][mesh::kHexFaceNodes[face.localFace][k]];
  return nodes;
}

DeformablePair pairFaces(const mesh::HexMesh &mesh, const std::vector<mesh::ElementFace> &slaveFaces,
                         std::vector<mesh::ElementFace> masterFaces, bool self, double searchRadius,
                         double margin, SlaveRule rule, int pointsPerDirection) {
  DeformablePair pair;
  pair.self = self;
  pair.margin = margin;
  pair.masterFaces = std::move(masterFaces);
  if (!self) {
    const std::set<mesh::ElementFace> slave(slaveFaces.begin(), slaveFaces.end());
    for (const mesh::ElementFace &f : pair.masterFaces)
      if (slave.count(f))
        throw std::invalid_argument("the slave and master face sets share the face " +
                                    std::to_string(f.localFace) + " of element " + std::to_string(f.element) +
                                    "; a face set against itself is self-contact");
  }
  std::vector<Box> slaveBoxes, masterBoxes;
  for (const auto &f : slaveFaces) slaveBoxes.push_back(boxOf(mesh, f));
  for (const auto &f : pair.masterFaces) masterBoxes.push_back(boxOf(mesh, f));
  pair.candidates = boxesWithinReach(slaveBoxes, masterBoxes, searchRadius + margin);
  if (self)  // a face never meets one it shares a node with (they touch along their common edge)
    for (std::size_t i = 0; i < slaveFaces.size(); ++i) {
      const auto own = faceNodeIds(mesh, slaveFaces[i]);
      auto &list = pair.candidates[i];
      list.erase(std::remove_if(list.begin(), list.end(),
                                [&](std::uint32_t m) {
                                  const auto other = faceNodeIds(mesh, pair.masterFaces[m]);
                                  return std::any_of(other.begin(), other.end(), [&](mesh::NodeId n) {
                                    return std::find(own.begin(), own.end(), n) != own.end();
                                  });
                                }),
                 list.end());
    }
  pair.points.resize(slaveFaces.size());
  std::size_t most = 0;
  for (std::size_t i = 0; i < slaveFaces.size(); ++i) {
    if (rule == SlaveRule::gauss) {
      pair.points[i] = slavePoints(pointsPerDirection);
    } else {
      std::vector<loads::FaceNodes> masters;
      for (std::uint32_t m : pair.candidates[i]) masters.push_back(referenceNodes(mesh, pair.masterFaces[m]));
      pair.points[i] = segmentedSlavePoints(referenceNodes(mesh, slaveFaces[i]), masters);
    }
    most = std::max(most, pair.points[i].size());
  }
  for (auto &points : pair.points) points.resize(most, SlavePoint{Eigen::Vector2d::Zero(), 0.0});
  return pair;
}

loads::FaceNodes referenceNodes(const mesh::HexMesh &mesh, const mesh::ElementFace &face) {
  loads::FaceNodes X;
  const auto nodes = faceNodeIds(mesh, face);
  for (int k = 0; k < 4; ++k) X.row(k) = mesh.nodes[static_cast<std::size_t>(nodes[k])].transpose();
  return X;
}

std::vector<mesh::NodeId> coupledNodes(const mesh::HexMesh &mesh,
                                       const std::vector<mesh::ElementFace> &slaveFaces,
                                       const DeformablePair &pair, std::size_t slaveFace) {
  const auto own = faceNodeIds(mesh, slaveFaces[slaveFace]);
  std::vector<mesh::NodeId> nodes(own.begin(), own.end());
  for (std::uint32_t m : pair.candidates[slaveFace]) {
    const auto other = faceNodeIds(mesh, pair.masterFaces[m]);
    nodes.insert(nodes.end(), other.begin(), other.end());
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

std::optional<PairMatch> closestMasterFace(const Eigen::Vector3d &x, const Eigen::Vector3d &slaveNormal,
                                           const std::vector<std::uint32_t> &candidates,
                                           const std::function<loads::FaceNodes(std::uint32_t)> &masterAt,
                                           double searchRadius) {
  std::optional<PairMatch> best;
  for (std::uint32_t m : candidates) {
    const std::optional<FaceProjection> p = projectOntoFace(masterAt(m), x);
    if (!p || !p->inside || std::abs(p->gap) > searchRadius || p->normal.dot(slaveNormal) >= 0.0) continue;
    if (!best || std::abs(p->gap) < std::abs(best->projection.gap)) best = PairMatch{m, *p};
  }
  return best;
}

}  // namespace glossa::contact
