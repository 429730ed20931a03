// partitionElements: balance, compactness and determinism of recursive coordinate bisection.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

#include "mesh/BoxGenerator.hpp"
#include "mesh/CookMembraneGenerator.hpp"
#include "mesh/HexMesh.hpp"
#include "mesh/Partition.hpp"

namespace glossa::mesh {
namespace {

std::vector<std::size_t> partSizes(const std::vector<int> &owner, int parts) {
  std::vector<std::size_t> sizes(static_cast<std::size_t>(parts), 0);
  for (int p : owner) {
    EXPECT_GE(p, 0);
    EXPECT_LT(p, parts);
    if (p >= 0 && p < parts) ++sizes[static_cast<std::size_t>(p)];
  }
  return sizes;
}

// Number of face-connected components of the elements owned by `part` (0 for an empty part).
// Two elements are neighbours when they share four nodes.
int connectedComponents(const HexMesh &mesh, const std::vector<int> &owner, int part) {
  std::map<std::array<NodeId, 4>, std::vector<std::size_t>> byFace;
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    if (owner[e] != part) continue;
    for (const auto &local : kHexFaceNodes) {
      std::array<NodeId, 4> key;
      for (int a = 0; a < 4; ++a) key[a] = mesh.elements[e][local[a]];
      std::sort(key.begin(), key.end());
      byFace[key].push_back(e);
    }
  }
  std::map<std::size_t, std::vector<std::size_t>> neighbours;
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    if (owner[e] == part) neighbours[e];
  }
  for (const auto &entry : byFace) {
    if (entry.second.size() == 2) {
      neighbours[entry.second[0]].push_back(entry.second[1]);
      neighbours[entry.second[1]].push_back(entry.second[0]);
    }
  }
  std::set<std::size_t> seen;
  int components = 0;
  for (const auto &entry : neighbours) {
    if (seen.count(entry.first)) continue;
    ++components;
    std::vector<std::size_t> stack = {entry.first};
    seen.insert(entry.first);
    while (!stack.empty()) {
      const std::size_t e = stack.back();
      stack.pop_back();
      for (std::size_t f : neighbours[e]) {
        if (seen.insert(f).second) stack.push_back(f);
      }
    }
  }
  return components;
}

// Sizes differ by at most one, and any two non-empty parts are separated by an axis-aligned
// plane through element centroids: the parts do not interleave. This is what bisection
// guarantees for any mesh and any part count; face-connectivity it guarantees only when no
// cut has to pass through a slab of elements with equal centroid coordinates.
void expectBalancedAndSeparated(const HexMesh &mesh, int parts) {
  const std::vector<int> owner = partitionElements(mesh, parts);
  ASSERT_EQ(owner.size(), mesh.numElements());
  const std::vector<std::size_t> sizes = partSizes(owner, parts);
  const auto [smallest, largest] = std::minmax_element(sizes.begin(), sizes.end());
  EXPECT_LE(*largest - *smallest, std::size_t{1}) << parts << " parts";
  EXPECT_EQ(*smallest, mesh.numElements() / static_cast<std::size_t>(parts)) << parts << " parts";

  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Eigen::Vector3d> lo(sizes.size(), Eigen::Vector3d::Constant(inf));
  std::vector<Eigen::Vector3d> hi(sizes.size(), Eigen::Vector3d::Constant(-inf));
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    const Eigen::Vector3d c =
        mesh.elementCoordinates(static_cast<ElementId>(e)).colwise().mean().transpose();
    const auto p = static_cast<std::size_t>(owner[e]);
    lo[p] = lo[p].cwiseMin(c);
    hi[p] = hi[p].cwiseMax(c);
  }
  for (std::size_t a = 0; a < sizes.size(); ++a) {
    for (std::size_t b = a + 1; b < sizes.size(); ++b) {
      if (sizes[a] == 0 || sizes[b] == 0) continue;
      const bool separated =
          ((hi[a].array() <= lo[b].array()) || (hi[b].array() <= lo[a].array())).any();
      EXPECT_TRUE(separated) << parts << " parts: parts " << a << " and " << b << " interleave";
    }
  }
}

TEST(Partition, BalancedAndSeparatedForAnyPartCount) {
  const HexMesh box = generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {4, 4, 4});
  const HexMesh cook = generateCookMembrane(5, 2, 1.0, 1e-3);
  for (int parts = 1; parts <= 13; ++parts) {
    expectBalancedAndSeparated(box, parts);
    expectBalancedAndSeparated(cook, parts);
  }
}

TEST(Partition, PowerOfTwoPartsOfACubeAreConnectedBlocks) {
  // 4x4x4 elements in 2^m parts: every cut falls between slabs, so each part is a block of
  // 64 / 2^m elements that is face-connected and fills its bounding box.
  const HexMesh mesh = generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {4, 4, 4});
  const double h = 0.25;
  for (int parts : {1, 2, 4, 8, 16, 32, 64}) {
    const std::vector<int> owner = partitionElements(mesh, parts);
    for (int p = 0; p < parts; ++p) {
      EXPECT_EQ(connectedComponents(mesh, owner, p), 1) << parts << " parts, part " << p;
      Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
      int count = 0;
      for (std::size_t e = 0; e < mesh.numElements(); ++e) {
        if (owner[e] != p) continue;
        ++count;
        const Eigen::Matrix<double, 8, 3> X = mesh.elementCoordinates(static_cast<ElementId>(e));
        lo = lo.cwiseMin(X.colwise().minCoeff().transpose());
        hi = hi.cwiseMax(X.colwise().maxCoeff().transpose());
      }
      EXPECT_EQ(count, 64 / parts);
      EXPECT_NEAR((hi - lo).prod(), count * h * h * h, 1e-12) << parts << " parts, part " << p;
    }
  }
}

TEST(Partition, TwoPartsOfACubeAreHalfBoxes) {
  const int n = 4;
  const HexMesh mesh =
      generateBox(Eigen::Vector3d(3, -7, 1), Eigen::Vector3d::Constant(2), {n, n, n});
  const std::vector<int> owner = partitionElements(mesh, 2);
  // Equal extents: the tie goes to x, so part 0 is i < n/2 and part 1 is i >= n/2.
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        EXPECT_EQ(owner[static_cast<std::size_t>(i + n * (j + n * k))], i < n / 2 ? 0 : 1);
      }
    }
  }
}

TEST(Partition, EightPartsOfACubeAreOctants) {
  const int n = 4;
  const HexMesh mesh = generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {n, n, n});
  const std::vector<int> owner = partitionElements(mesh, 8);
  // Every octant (i/2, j/2, k/2) is owned by a single part, and the eight owners differ.
  std::map<int, std::set<int>> ownersOfOctant;
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const int octant = i / 2 + 2 * (j / 2) + 4 * (k / 2);
        ownersOfOctant[octant].insert(owner[static_cast<std::size_t>(i + n * (j + n * k))]);
      }
    }
  }
  std::set<int> distinct;
  for (const auto &entry : ownersOfOctant) {
    ASSERT_EQ(entry.second.size(), std::size_t{1}) << "octant " << entry.first;
    distinct.insert(*entry.second.begin());
  }
  EXPECT_EQ(distinct.size(), std::size_t{8});
}

TEST(Partition, SplitsAcrossTheLongestExtent) {
  // A 4 x 1 x 1 bar with cells 8 x 2 x 2: both parts must be x-halves, not y or z slabs.
  const HexMesh mesh = generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d(4, 1, 1), {8, 2, 2});
  const std::vector<int> owner = partitionElements(mesh, 2);
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    const double xc = mesh.elementCoordinates(static_cast<ElementId>(e)).col(0).mean();
    EXPECT_EQ(owner[e], xc < 2.0 ? 0 : 1) << e;
  }
}

TEST(Partition, DeterministicAndEdgeCases) {
  const HexMesh mesh = generateCookMembrane(4, 1, 1.0, 1.0);
  EXPECT_EQ(partitionElements(mesh, 5), partitionElements(mesh, 5));
  EXPECT_EQ(partitionElements(mesh, 1), std::vector<int>(mesh.numElements(), 0));
  // More parts than elements: every element alone, the remaining parts empty.
  const std::vector<int> owner = partitionElements(mesh, 20);
  const std::vector<std::size_t> sizes = partSizes(owner, 20);
  EXPECT_EQ(std::count(sizes.begin(), sizes.end(), std::size_t{1}), 16);
  EXPECT_EQ(std::count(sizes.begin(), sizes.end(), std::size_t{0}), 4);
  EXPECT_THROW(partitionElements(mesh, 0), std::invalid_argument);
}

}  // namespace
}  // namespace glossa::mesh
