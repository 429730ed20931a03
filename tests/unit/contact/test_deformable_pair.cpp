// The pairing of a deformable pair's faces (contact/DeformablePair): candidates by reference
// distance (search radius + margin), self-contact leaving out a face's own and its neighbours, a
// face set against itself refused unless self-contact is asked, the coupled nodes, and the search
// of a point among its candidates (inside, within the radius, facing it, the nearest).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <stdexcept>

#include "StackedBoxes.hpp"
#include "contact/DeformablePair.hpp"

using namespace glossa;
using namespace glossa::contact;

namespace {

// Two 1 x 1 boxes of 2 x 2 x 1 cells, the upper `gap` above the lower.
mesh::HexMesh twoBoxes(double gap) { return test::stackedBoxes(1.0, {2, 2, 1}, {2, 2, 1}, gap); }

}  // namespace

TEST(DeformablePair, CandidatesLieWithinTheSearchRadiusAndMargin) {
  const mesh::HexMesh m = twoBoxes(0.1);
  const auto &slave = m.faceSets.at("upper bottom"), &master = m.faceSets.at("lower top");
  ASSERT_EQ(slave.size(), 4u);
  // The faces are 0.1 apart: a reach of 0.05 pairs nothing, 0.15 pairs each slave face with the
  // master face below it and its neighbours (boxes touching at an edge or corner count).
  const DeformablePair none = pairFaces(m, slave, master, false, 0.02, 0.03, SlaveRule::gauss, 2);
  for (const auto &c : none.candidates) EXPECT_TRUE(c.empty());
  const DeformablePair all = pairFaces(m, slave, master, false, 0.05, 0.1, SlaveRule::gauss, 3);
  EXPECT_EQ(all.pointsPerFace(), 9u);
  for (const auto &c : all.candidates) EXPECT_EQ(c.size(), 4u);
  // Coupled: the slave face's 4 nodes and the master top's 9.
  EXPECT_EQ(coupledNodes(m, slave, all, 0).size(), 13u);
  EXPECT_THROW(pairFaces(m, master, master, false, 0.05, 0.1, SlaveRule::gauss, 2), std::invalid_argument);
}

// The box sweep finds exactly the pairs an all-pairs test of the boxes' Euclidean distance finds,
// sorted: non-matching grids (7 x 5 over 4 x 6), the upper one tilted so that the reach cuts
// through it, and reaches from none to every pair.
TEST(DeformablePair, CandidatesAreThoseOfAnAllPairsTest) {
  mesh::HexMesh m = test::stackedBoxes(1.0, {4, 6, 1}, {7, 5, 1}, 0.05);
  for (auto &x : m.nodes)
    if (x(2) > 1.0) x(2) += 0.3 * x(0) + 0.1 * x(1);
  const auto &slave = m.faceSets.at("upper bottom"), &master = m.faceSets.at("lower top");
  const auto box = [&](const mesh::ElementFace &f) {
    Eigen::AlignedBox3d b;
    for (mesh::NodeId n : faceNodeIds(m, f)) b.extend(m.nodes[n]);
    return b;
  };
  for (double reach : {0.01, 0.1, 0.2, 0.4, 2.0}) {
    const DeformablePair pair = pairFaces(m, slave, master, false, 0.5 * reach, 0.5 * reach, SlaveRule::gauss, 2);
    std::size_t found = 0;
    for (std::size_t i = 0; i < slave.size(); ++i) {
      std::vector<std::uint32_t> expected;
      for (std::size_t j = 0; j < master.size(); ++j) {
        const Eigen::AlignedBox3d a = box(slave[i]), b = box(master[j]);
        const Eigen::Vector3d apart = (a.min() - b.max()).cwiseMax(b.min() - a.max()).cwiseMax(0.0);
        if (apart.norm() <= reach) expected.push_back(static_cast<std::uint32_t>(j));
      }
      EXPECT_EQ(pair.candidates[i], expected) << "reach " << reach << ", slave face " << i;
      found += expected.size();
    }
    if (reach == 0.01) {
      EXPECT_EQ(found, 0u);
    }
    if (reach == 2.0) {
      EXPECT_EQ(found, slave.size() * master.size());
    }
  }
}

TEST(DeformablePair, SelfContactLeavesOutAFacesOwnAndNeighbours) {
  const mesh::HexMesh m = twoBoxes(0.1);
  std::vector<mesh::ElementFace> walls = m.faceSets.at("lower top");
  const auto &bottom = m.faceSets.at("upper bottom");
  walls.insert(walls.end(), bottom.begin(), bottom.end());
  const DeformablePair self = pairFaces(m, walls, walls, true, 0.05, 0.1, SlaveRule::gauss, 2);
  ASSERT_EQ(self.candidates.size(), 8u);
  for (std::size_t i = 0; i < walls.size(); ++i) {
    // Every face of its own wall shares a node with it (a 2 x 2 wall): only the other wall's four.
    EXPECT_EQ(self.candidates[i].size(), 4u) << i;
    for (std::uint32_t c : self.candidates[i]) EXPECT_NE(c < 4, i < 4) << i;
  }
}

TEST(DeformablePair, SearchFindsTheNearestFacingFaceInside) {
  loads::FaceNodes near, far, away, behind;
  near << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;  // normal +z, 0.1 below the point
  far = near;
  far.col(2).array() -= 0.05;  // 0.15 below
  away = near;
  away.col(0).array() += 2.0;                            // beside: the projection lands outside
  behind << 0, 0, 0.2, 0, 1, 0.2, 1, 1, 0.2, 1, 0, 0.2;  // normal -z, above the point: not facing
  const std::vector<loads::FaceNodes> faces{far, away, behind, near};
  const auto at = [&](std::uint32_t m) { return faces[m]; };
  const Eigen::Vector3d x(0.4, 0.6, 0.1), down(0, 0, -1);
  const auto match = closestMasterFace(x, down, {0, 1, 2, 3}, at, 0.5);
  ASSERT_TRUE(match.has_value());
  EXPECT_EQ(match->master, 3u);
  EXPECT_NEAR(match->projection.gap, 0.1, 1e-14);
  EXPECT_FALSE(closestMasterFace(x, down, {0, 1, 2, 3}, at, 0.05).has_value()) << "beyond the search radius";
  EXPECT_FALSE(closestMasterFace(x, down, {1, 2}, at, 0.5).has_value());
  EXPECT_FALSE(closestMasterFace(x, Eigen::Vector3d(0, 0, 1), {0, 3}, at, 0.5).has_value()) << "not facing";
}
