// generateBox and the HexMesh queries, checked against closed-form box geometry.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "MeshTestChecks.hpp"
#include "mesh/BoxGenerator.hpp"
#include "mesh/HexMesh.hpp"
#include "mesh/MeshQuality.hpp"

namespace glossa::mesh {
namespace {

const std::array<std::string, 6> kSides = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};

// A deliberately uneven box away from the origin, so that axis mix-ups show.
const Eigen::Vector3d kOrigin(-1.0, 2.0, 0.5);
const Eigen::Vector3d kLengths(3.0, 0.5, 2.0);
const std::array<int, 3> kCells = {3, 4, 5};

HexMesh unevenBox() { return generateBox(kOrigin, kLengths, kCells); }

TEST(BoxGenerator, CountsAndNumbering) {
  const HexMesh mesh = unevenBox();
  const int nx = 3, ny = 4, nz = 5;
  ASSERT_EQ(mesh.numNodes(), std::size_t{4 * 5 * 6});
  ASSERT_EQ(mesh.numElements(), std::size_t{3 * 4 * 5});
  const Eigen::Vector3d h(3.0 / nx, 0.5 / ny, 2.0 / nz);
  for (int k = 0; k <= nz; ++k) {
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) {
        const NodeId n = i + (nx + 1) * (j + (ny + 1) * k);
        const Eigen::Vector3d expected = kOrigin + Eigen::Vector3d(i * h.x(), j * h.y(), k * h.z());
        EXPECT_LT((mesh.nodes[static_cast<std::size_t>(n)] - expected).norm(), 1e-14);
      }
    }
  }
  // Element (i,j,k) = (1,2,3): its node 0 is grid node (1,2,3), node 6 grid node (2,3,4).
  const ElementId e = 1 + nx * (2 + ny * 3);
  const Hex &hex = mesh.elements[static_cast<std::size_t>(e)];
  EXPECT_EQ(hex[0], 1 + (nx + 1) * (2 + (ny + 1) * 3));
  EXPECT_EQ(hex[6], 2 + (nx + 1) * (3 + (ny + 1) * 4));
}

TEST(BoxGenerator, ElementCoordinatesFollowVtkOrder) {
  const HexMesh mesh = generateBox(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(2, 4, 6), {2, 2, 2});
  const Eigen::Matrix<double, 8, 3> X = mesh.elementCoordinates(0);
  const double xi[8] = {-1, +1, +1, -1, -1, +1, +1, -1};
  const double eta[8] = {-1, -1, +1, +1, -1, -1, +1, +1};
  const double zeta[8] = {-1, -1, -1, -1, +1, +1, +1, +1};
  for (int a = 0; a < 8; ++a) {
    // Element 0 spans [1,2] x [2,4] x [3,6].
    EXPECT_DOUBLE_EQ(X(a, 0), 1.5 + 0.5 * xi[a]);
    EXPECT_DOUBLE_EQ(X(a, 1), 3.0 + 1.0 * eta[a]);
    EXPECT_DOUBLE_EQ(X(a, 2), 4.5 + 1.5 * zeta[a]);
  }
  EXPECT_THROW(mesh.elementCoordinates(8), std::out_of_range);
  EXPECT_THROW(mesh.elementCoordinates(-1), std::out_of_range);
}

TEST(BoxGenerator, VolumeIsProductOfLengths) {
  EXPECT_NEAR(meshVolume(unevenBox()), 3.0 * 0.5 * 2.0, 1e-13);
}

TEST(BoxGenerator, AllElementsAreUndistortedAndPositive) {
  const auto [lo, hi] = scaledJacobianRange(unevenBox());
  EXPECT_NEAR(lo, 1.0, 1e-12);
  EXPECT_NEAR(hi, 1.0, 1e-12);
}

TEST(BoxGenerator, CubeSetSizes) {
  for (int n : {1, 2, 5}) {
    const HexMesh mesh = generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {n, n, n});
    for (const std::string &side : kSides) {
      EXPECT_EQ(mesh.nodeSet(side).size(), static_cast<std::size_t>((n + 1) * (n + 1))) << side;
      EXPECT_EQ(mesh.faceSet(side).size(), static_cast<std::size_t>(n * n)) << side;
    }
    EXPECT_EQ(mesh.elementSets.at("all").size(), static_cast<std::size_t>(n * n * n));
  }
}

TEST(BoxGenerator, SidesLieOnTheirPlanesWithOutwardNormals) {
  const HexMesh mesh = unevenBox();
  const Eigen::Vector3d far = kOrigin + kLengths;
  // (axis, coordinate, size of face set, size of node set) for each side.
  struct Side {
    int axis;
    double value;
    std::size_t faces, nodes;
  };
  const std::array<Side, 6> expected = {{{0, kOrigin.x(), 4 * 5, 5 * 6},
                                         {0, far.x(), 4 * 5, 5 * 6},
                                         {1, kOrigin.y(), 3 * 5, 4 * 6},
                                         {1, far.y(), 3 * 5, 4 * 6},
                                         {2, kOrigin.z(), 3 * 4, 4 * 5},
                                         {2, far.z(), 3 * 4, 4 * 5}}};
  for (int s = 0; s < 6; ++s) {
    const std::string &name = kSides[static_cast<std::size_t>(s)];
    const Side &side = expected[static_cast<std::size_t>(s)];
    EXPECT_EQ(mesh.faceSet(name).size(), side.faces) << name;
    EXPECT_EQ(mesh.nodeSet(name).size(), side.nodes) << name;
    for (NodeId n : mesh.nodeSet(name)) {
      EXPECT_EQ(mesh.nodes[static_cast<std::size_t>(n)][side.axis], side.value) << name;
    }
    testing::expectOutwardNormals(mesh, name);
    testing::expectNodeSetMatchesFaces(mesh, name);
    EXPECT_TRUE(std::is_sorted(mesh.faceSet(name).begin(), mesh.faceSet(name).end()));
  }
}

TEST(BoxGenerator, SidesPartitionTheBoundary) {
  const HexMesh mesh = unevenBox();
  const std::vector<ElementFace> boundary = boundaryFaces(mesh);
  EXPECT_EQ(boundary.size(), std::size_t{2 * (3 * 4 + 4 * 5 + 3 * 5)});
  std::vector<ElementFace> sides;
  for (const std::string &name : kSides) {
    sides.insert(sides.end(), mesh.faceSet(name).begin(), mesh.faceSet(name).end());
  }
  std::sort(sides.begin(), sides.end());
  EXPECT_EQ(sides, boundary);
}

// Selecting boundary faces by the way they face: on a box each side is the set of boundary faces
// whose outward normal is that side's axis; a diagonal direction with cos 45 deg picks two sides.
TEST(HexMesh, FacesFacingSelectsSidesByOutwardNormal) {
  const HexMesh mesh = unevenBox();
  const std::vector<ElementFace> boundary = boundaryFaces(mesh);
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {-1, 1}) {
      const Eigen::Vector3d d = sign * Eigen::Vector3d::Unit(axis);
      auto expected = mesh.faceSet(kSides[2 * axis + (sign > 0)]);
      std::sort(expected.begin(), expected.end());
      EXPECT_EQ(facesFacing(mesh, boundary, 7.0 * d, 0.5), expected) << kSides[2 * axis + (sign > 0)];
      for (const ElementFace &f : expected) EXPECT_NEAR(faceOutwardNormal(mesh, f).dot(d), 1.0, 1e-14);
    }
  // (1, 0, 1)/sqrt(2): xmax and zmax have cosine 0.7071 >= 0.7, every other side 0 or less.
  auto both = mesh.faceSet("xmax");
  both.insert(both.end(), mesh.faceSet("zmax").begin(), mesh.faceSet("zmax").end());
  std::sort(both.begin(), both.end());
  EXPECT_EQ(facesFacing(mesh, boundary, {1, 0, 1}, 0.7), both);
  EXPECT_TRUE(facesFacing(mesh, boundary, {1, 0, 1}, 0.71).empty());
  EXPECT_THROW(facesFacing(mesh, boundary, Eigen::Vector3d::Zero(), 0.0), std::invalid_argument);
}

TEST(BoxGenerator, NamedPointOnlyOrigin) {
  const HexMesh mesh = unevenBox();
  ASSERT_EQ(mesh.namedPoints.size(), std::size_t{1});
  const NamedPoint &p = mesh.namedPoints.at("origin");
  EXPECT_EQ(p.node, 0);
  EXPECT_EQ(p.position, kOrigin);
}

TEST(BoxGenerator, RejectsBadInputNamingTheParameter) {
  auto messageOf = [](const Eigen::Vector3d &origin, const Eigen::Vector3d &lengths,
                      const std::array<int, 3> &cells) -> std::string {
    try {
      generateBox(origin, lengths, cells);
    } catch (const std::invalid_argument &e) {
      return e.what();
    }
    return "no exception";
  };
  const Eigen::Vector3d O = Eigen::Vector3d::Zero(), L = Eigen::Vector3d::Ones();
  EXPECT_NE(messageOf(O, L, {1, 0, 1}).find("cells[1]"), std::string::npos);
  EXPECT_NE(messageOf(O, L, {1, 1, -2}).find("cells[2]"), std::string::npos);
  EXPECT_NE(messageOf(O, Eigen::Vector3d(0, 1, 1), {1, 1, 1}).find("lengths[0]"),
            std::string::npos);
  EXPECT_NE(messageOf(O, Eigen::Vector3d(1, -1, 1), {1, 1, 1}).find("lengths[1]"),
            std::string::npos);
  EXPECT_NE(messageOf(O, Eigen::Vector3d(1, 1, NAN), {1, 1, 1}).find("lengths[2]"),
            std::string::npos);
  EXPECT_NE(messageOf(Eigen::Vector3d(0, INFINITY, 0), L, {1, 1, 1}).find("origin[1]"),
            std::string::npos);
}

TEST(HexMesh, UnknownSetErrorListsKnownSets) {
  const HexMesh mesh = unevenBox();
  try {
    mesh.nodeSet("xmni");
    FAIL() << "no exception";
  } catch (const std::runtime_error &e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'xmni'"), std::string::npos) << what;
    for (const std::string &side : kSides) EXPECT_NE(what.find(side), std::string::npos) << what;
  }
  EXPECT_THROW(mesh.faceSet("all"), std::runtime_error);
  EXPECT_THROW(mesh.nodesOfFaceSet("nope"), std::runtime_error);
}

TEST(HexMesh, NearestNode) {
  const HexMesh mesh = generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {2, 2, 2});
  // Grid nodes at 0, 0.5, 1; node (i,j,k) has id i + 3 (j + 3 k).
  EXPECT_EQ(mesh.nearestNode(Eigen::Vector3d(0.9, 0.6, 0.1)), 2 + 3 * (1 + 3 * 0));
  EXPECT_EQ(mesh.nearestNode(Eigen::Vector3d(5, 5, 5)), 26);
  // Equidistant from nodes 0 and 1: the lower id wins.
  EXPECT_EQ(mesh.nearestNode(Eigen::Vector3d(0.25, 0, 0)), 0);
  EXPECT_THROW(HexMesh{}.nearestNode(Eigen::Vector3d::Zero()), std::runtime_error);
}

TEST(HexMesh, FaceCentroid) {
  const HexMesh mesh = generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 4, 6), {1, 1, 1});
  EXPECT_EQ(faceCentroid(mesh, {0, 3}), Eigen::Vector3d(2, 2, 3));  // xi = +1
  EXPECT_EQ(faceCentroid(mesh, {0, 0}), Eigen::Vector3d(1, 2, 0));  // zeta = -1
}

TEST(HexMesh, FlatBoxSelectsThePlane) {
  const HexMesh mesh = unevenBox();
  const Eigen::Vector3d far = kOrigin + kLengths;
  // A zero-thickness box in the plane x = far.x, slightly off in the last bit: the relative
  // tolerance must still pick exactly the xmax side.
  const Eigen::Vector3d lo(far.x() * (1 + 1e-15), kOrigin.y(), kOrigin.z());
  const Eigen::Vector3d hi(far.x(), far.y(), far.z());
  EXPECT_EQ(facesInBox(mesh, boundaryFaces(mesh), lo, hi), mesh.faceSet("xmax"));
  EXPECT_EQ(nodesInBox(mesh, lo, hi), mesh.nodeSet("xmax"));
  // Half of the zmin side: x in [-1, 0.5] picks the faces whose centroids are at x = -0.5, 0.5.
  const auto half = facesInBox(mesh, mesh.faceSet("zmin"), Eigen::Vector3d(-1, 2, 0.5),
                               Eigen::Vector3d(0.5, 2.5, 0.5));
  EXPECT_EQ(half.size(), std::size_t{2 * 4});
  for (const ElementFace &f : half) EXPECT_LE(faceCentroid(mesh, f).x(), 0.5);
  // A box off the mesh selects nothing.
  EXPECT_TRUE(
      nodesInBox(mesh, Eigen::Vector3d::Constant(10), Eigen::Vector3d::Constant(11)).empty());
}

}  // namespace
}  // namespace glossa::mesh
