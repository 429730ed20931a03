// Uniform refinement against closed forms: a refined box is the box generated with twice the
// cells; volumes of affine and of trilinear (tongue) elements are preserved; sets scale by 8
// (elements) and 4 (faces); node counts follow N + edges + faces + cells.

#include <gtest/gtest.h>

#include <set>

#include "ImportTestSupport.hpp"
#include "MeshTestChecks.hpp"
#include "mesh/AnsysReader.hpp"
#include "mesh/BoxGenerator.hpp"
#include "mesh/MeshQuality.hpp"
#include "mesh/MeshRefinement.hpp"

namespace glossa::mesh {
namespace {

std::vector<std::array<double, 3>> sortedPositions(const HexMesh &mesh) {
  std::vector<std::array<double, 3>> p;
  for (const auto &x : mesh.nodes) p.push_back({x.x(), x.y(), x.z()});
  std::sort(p.begin(), p.end());
  return p;
}

TEST(MeshRefinement, BoxIsTheBoxWithTwiceTheCells) {
  const Eigen::Vector3d origin(1, -2, 0.5), lengths(2, 3, 4);
  const HexMesh coarse = generateBox(origin, lengths, {2, 3, 4});
  for (int levels : {1, 2}) {
    const HexMesh fine = refineUniformly(coarse, levels);
    const int s = 1 << levels;
    EXPECT_EQ(fine.numElements(), coarse.numElements() * static_cast<std::size_t>(s * s * s));
    EXPECT_EQ(fine.numNodes(), static_cast<std::size_t>((2 * s + 1) * (3 * s + 1) * (4 * s + 1)));
    // Same node positions as the generator's finer box (exact: midpoints of dyadic grids).
    const HexMesh reference = generateBox(origin, lengths, {2 * s, 3 * s, 4 * s});
    const auto a = sortedPositions(fine), b = sortedPositions(reference);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      for (int d = 0; d < 3; ++d) EXPECT_NEAR(a[i][d], b[i][d], 1e-14) << i;
    }
    // No duplicate nodes: sorted positions strictly increase.
    for (std::size_t i = 1; i < a.size(); ++i) EXPECT_LT(a[i - 1], a[i]);
    EXPECT_NEAR(meshVolume(fine), 24.0, 1e-12);
    for (std::size_t e = 0; e < fine.numElements(); ++e) {
      EXPECT_NEAR(scaledJacobian(fine.elementCoordinates(static_cast<ElementId>(e))), 1.0, 1e-12);
    }
    EXPECT_EQ(fine.elementSets.at("all").size(), 24u * s * s * s);
    for (const std::string side : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}) {
      EXPECT_EQ(fine.faceSets.at(side).size(), coarse.faceSets.at(side).size() * s * s) << side;
      EXPECT_EQ(fine.faceSets.at(side).size(), reference.faceSets.at(side).size()) << side;
      testing::expectOutwardNormals(fine, side);
      // The node-set rule gives exactly the nodes of the refined faces.
      testing::expectNodeSetMatchesFaces(fine, side);
      EXPECT_EQ(fine.nodeSets.at(side).size(), reference.nodeSets.at(side).size()) << side;
    }
    for (const ElementFace &f : fine.faceSets.at("xmax")) EXPECT_NEAR(faceCentroid(fine, f).x(), 3.0, 1e-14);
    // The refined boundary is the refined face sets.
    std::vector<ElementFace> sides;
    for (const auto &[name, faces] : fine.faceSets) sides.insert(sides.end(), faces.begin(), faces.end());
    std::sort(sides.begin(), sides.end());
    EXPECT_EQ(sides, boundaryFaces(fine));
    EXPECT_EQ(fine.namedPoints.at("origin").node, coarse.namedPoints.at("origin").node);
    EXPECT_EQ(fine.nodes[static_cast<std::size_t>(fine.namedPoints.at("origin").node)], origin);
  }
}

TEST(MeshRefinement, AffineVolumeAndLevelsArgument) {
  HexMesh mesh = generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 1), {2, 1, 3});
  Eigen::Matrix3d A;
  A << 1.5, 0.4, -0.2, 0.1, 0.9, 0.3, 0.0, -0.25, 1.2;
  for (auto &x : mesh.nodes) x = A * x + Eigen::Vector3d(0.3, 0.2, -1);
  const HexMesh fine = refineUniformly(mesh, 2);
  EXPECT_NEAR(meshVolume(fine), A.determinant(), 1e-13);  // round-off of a 384-term sum
  for (std::size_t e = 0; e < fine.numElements(); ++e) {
    // An affine image of a 1/8 x 1/4 x 1/12 box: det(dX/dxi) = det(A) V_child / 8 everywhere.
    EXPECT_NEAR(minGaussPointJacobian(fine.elementCoordinates(static_cast<ElementId>(e))),
                A.determinant() / (8.0 * 4.0 * 12.0) / 8.0, 1e-15);
  }
  const HexMesh same = refineUniformly(mesh, 0);
  EXPECT_EQ(same.nodes, mesh.nodes);
  EXPECT_EQ(same.elements, mesh.elements);
  EXPECT_THROW(refineUniformly(mesh, -1), std::invalid_argument);
}

// A geometry given on the coarse mesh (a zero-strain configuration) carried to the refinement:
// refinement commutes with an affine map, so moving the coarse nodes by A x + b and refining gives
// the refined nodes moved by the same map.
TEST(MeshRefinement, PositionsOfTheCoarseMeshAreCarriedToTheRefinement) {
  const HexMesh coarse = generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 2, 1), {2, 3, 2});
  Eigen::Matrix3d A;
  A << 1.1, 0.3, -0.2, 0.0, 0.8, 0.25, 0.1, -0.3, 1.3;
  const Eigen::Vector3d b(0.5, -1.0, 2.0);
  std::vector<Eigen::Vector3d> moved;
  for (const auto &x : coarse.nodes) moved.push_back(A * x + b);
  for (int levels : {0, 1, 2}) {
    const HexMesh fine = refineUniformly(coarse, levels);
    const auto carried = refinedPositions(coarse, moved, levels);
    ASSERT_EQ(carried.size(), fine.numNodes());
    for (std::size_t n = 0; n < carried.size(); ++n)
      EXPECT_LT((carried[n] - (A * fine.nodes[n] + b)).norm(), 1e-14) << levels << " " << n;
  }
  EXPECT_THROW(refinedPositions(coarse, std::vector<Eigen::Vector3d>(3), 1), std::invalid_argument);
  EXPECT_THROW(refinedPositions(coarse, moved, -1), std::invalid_argument);
}

TEST(MeshRefinement, TongueKeepsVolumeSetsAndBoundary) {
  const std::string dir = std::string(GLOSSA_SOURCE_DIR) + "/inputs/tongue/";
  AnsysModelFiles files;
  files.nodes = dir + "tongue.node";
  files.elements = dir + "tongue.elem";
  files.components = dir + "CreateMuscles.mac";
  files.nodeSets = {{"jaw", dir + "jaw_attachment_nodes.txt"}};
  HexMesh mesh = readAnsysModel(files).imported.mesh;
  mesh.faceSets["boundary"] = boundaryFaces(mesh);
  mesh.namedPoints["tip"] = {mesh.nodes[919], 919, {}};  // README: node 920

  // Distinct edges and faces counted here from the VTK hex directly.
  std::set<std::pair<NodeId, NodeId>> edges;
  std::set<std::array<NodeId, 4>> faces;
  const int edgeNodes[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  const int faceNodes[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                               {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (const Hex &h : mesh.elements) {
    for (const auto &e : edgeNodes) edges.insert(std::minmax(h[e[0]], h[e[1]]));
    for (const auto &f : faceNodes) {
      std::array<NodeId, 4> q{h[f[0]], h[f[1]], h[f[2]], h[f[3]]};
      std::sort(q.begin(), q.end());
      faces.insert(q);
    }
  }

  const HexMesh fine = refineUniformly(mesh, 1);
  EXPECT_EQ(fine.numElements(), 8u * 740u);
  EXPECT_EQ(fine.numNodes(), 946u + edges.size() + faces.size() + 740u);
  // Children are the parent's trilinear map on octants: the volume is unchanged for these
  // non-affine elements too, and the boundary still closes.
  const double V = meshVolume(mesh);
  EXPECT_NEAR(meshVolume(fine), V, 1e-13 * V);
  EXPECT_NEAR(testing::volumeByDivergence(fine), V, 1e-13 * V);
  for (std::size_t e = 0; e < fine.numElements(); ++e) {
    EXPECT_GT(minGaussPointJacobian(fine.elementCoordinates(static_cast<ElementId>(e))), 0.0) << e;
  }
  for (const auto &[name, set] : mesh.elementSets) {
    EXPECT_EQ(fine.elementSets.at(name).size(), 8 * set.size()) << name;
    double coarseVolume = 0, fineVolume = 0;
    for (ElementId e : set) coarseVolume += elementVolume(mesh.elementCoordinates(e));
    for (ElementId e : fine.elementSets.at(name)) fineVolume += elementVolume(fine.elementCoordinates(e));
    EXPECT_NEAR(fineVolume, coarseVolume, 1e-13 * V) << name;
  }
  EXPECT_EQ(fine.faceSets.at("boundary").size(), 4 * mesh.faceSets.at("boundary").size());
  EXPECT_EQ(fine.faceSets.at("boundary"), boundaryFaces(fine));
  testing::expectOutwardNormals(fine, "boundary");
  // Old nodes keep their ids: the jaw set still starts with its old nodes, the tip stays put.
  const auto &jaw = fine.nodeSets.at("jaw");
  EXPECT_TRUE(
      std::includes(jaw.begin(), jaw.end(), mesh.nodeSets.at("jaw").begin(), mesh.nodeSets.at("jaw").end()));
  EXPECT_GT(jaw.size(), mesh.nodeSets.at("jaw").size());
  EXPECT_EQ(fine.namedPoints.at("tip").node, 919);
  EXPECT_EQ(fine.nodes[919], mesh.nodes[919]);
}

}  // namespace
}  // namespace glossa::mesh
