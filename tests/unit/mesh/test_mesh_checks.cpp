// The mesh checks run before a solve: each fault a hostile mesh held (an unused node, coincident
// nodes, a duplicate element, an inverted element, and a corner the Gauss points miss) is found,
// a clean box has none, and parts are counted.
#include <gtest/gtest.h>

#include "mesh/BoxGenerator.hpp"
#include "mesh/MeshChecks.hpp"
#include "mesh/MeshQuality.hpp"

using namespace glossa::mesh;

namespace {
HexMesh box() { return generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 1, 1), {2, 1, 1}); }

bool clean(const MeshCheckReport &r) {
  return r.unusedNodes.empty() && r.coincidentNodes.empty() && r.duplicateElements.empty() && r.invertedCorners.empty();
}
} // namespace

TEST(MeshChecks, ACleanBoxHasNoFaultAndOnePart) {
  const HexMesh m = box();
  EXPECT_TRUE(clean(checkMesh(m)));
  EXPECT_EQ(meshParts(m).second, 1);
}

TEST(MeshChecks, FindsUnusedAndCoincidentNodes) {
  HexMesh m = box();
  const NodeId unused = static_cast<NodeId>(m.nodes.size());
  m.nodes.push_back({5, 5, 5});
  m.nodes.push_back(m.nodes[3] + Eigen::Vector3d(1e-9, 0, 0)); // at node 3, and used by no element either
  const MeshCheckReport r = checkMesh(m);
  EXPECT_EQ(r.unusedNodes, (std::vector<NodeId>{unused, unused + 1}));
  ASSERT_EQ(r.coincidentNodes.size(), 1u);
  EXPECT_EQ(r.coincidentNodes[0], std::make_pair(NodeId{3}, unused + 1));
  // A graded neighbour at a thousandth of the shortest edge is not coincident.
  HexMesh graded = box();
  graded.nodes.push_back(graded.nodes[3] + Eigen::Vector3d(1e-3, 0, 0));
  EXPECT_TRUE(checkMesh(graded).coincidentNodes.empty());
}

TEST(MeshChecks, FindsDuplicateElementsInAnyNodeOrder) {
  HexMesh m = box();
  Hex copy = m.elements[0];
  std::rotate(copy.begin(), copy.begin() + 3, copy.end());
  m.elements.push_back(copy);
  const MeshCheckReport r = checkMesh(m);
  ASSERT_EQ(r.duplicateElements.size(), 1u);
  EXPECT_EQ(r.duplicateElements[0], std::make_pair(ElementId{0}, ElementId{2}));
}

TEST(MeshChecks, FindsInvertedElementsAndCornersTheGaussPointsMiss) {
  HexMesh m = box();
  std::swap(m.elements[1][0], m.elements[1][4]); // mirrored: inside out
  std::swap(m.elements[1][1], m.elements[1][5]);
  std::swap(m.elements[1][2], m.elements[1][6]);
  std::swap(m.elements[1][3], m.elements[1][7]);
  MeshCheckReport r = checkMesh(m);
  ASSERT_EQ(r.invertedCorners.size(), 1u);
  EXPECT_EQ(r.invertedCorners[0].element, 1);
  EXPECT_LT(r.invertedCorners[0].scaledJacobian, 0.0);

  // A unit cube whose far top corner is pulled in to (0.55, 0.55, 0.55): det J > 0 at every
  // Gauss point, so the importers' check passes it, but the corner itself is inverted.
  HexMesh cube = generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {1, 1, 1});
  cube.nodes[cube.elements[0][6]] = Eigen::Vector3d::Constant(0.55);
  ASSERT_GT(minGaussPointJacobian(cube.elementCoordinates(0)), 0.0);
  r = checkMesh(cube);
  ASSERT_EQ(r.invertedCorners.size(), 1u);
  EXPECT_NEAR(r.invertedCorners[0].scaledJacobian, -0.588137, 1e-6); // by hand: corner 6's normalised det
}

TEST(MeshChecks, CountsPartsThatShareNoNode) {
  HexMesh m = box();
  const HexMesh other = generateBox(Eigen::Vector3d(5, 0, 0), Eigen::Vector3d::Ones(), {1, 1, 1});
  const NodeId offset = static_cast<NodeId>(m.nodes.size());
  m.nodes.insert(m.nodes.end(), other.nodes.begin(), other.nodes.end());
  Hex e = other.elements[0];
  for (NodeId &n : e) n += offset;
  m.elements.push_back(e);
  const auto [partOf, parts] = meshParts(m);
  EXPECT_EQ(parts, 2);
  EXPECT_EQ(partOf, (std::vector<int>{0, 0, 1}));
}
