// The closest-point search on triangulated surfaces (CGAL's AABB tree):
//  - the gap, point and normal of an octahedron against closed-form geometry on a face, an
//    edge, a corner and inside, and behind an open sheet (negative gap, as the face normal says);
//  - dNormal against central differences of the normal there;
//  - on the real palate, the tree against a scan of every triangle;
//  - the gaps of the tongue's boundary nodes to the palate, mandible and hyoid at rest against
//    the figures the data's README gives (measured there with other tools).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "ContactTestSurfaces.hpp"
#include "contact/ObjReader.hpp"
#include "contact/SurfaceProjection.hpp"
#include "contact/TriangulatedObstacle.hpp"
#include "mesh/AnsysReader.hpp"
#include "mesh/ImportTestSupport.hpp"

namespace {

using glossa::contact::ClosestPoint;
using glossa::contact::TriangulatedObstacle;
namespace ct = glossa::contact::testing;

constexpr double kAnywhere = std::numeric_limits<double>::infinity();
const std::string kTongue = std::string(GLOSSA_SOURCE_DIR) + "/inputs/tongue/";

ClosestPoint query(const TriangulatedObstacle &o, const Eigen::Vector3d &x) {
  const auto cp = o.closest(x, kAnywhere);
  EXPECT_TRUE(cp.has_value());
  return *cp;
}

void expectDNormalMatchesFiniteDifferences(const TriangulatedObstacle &o, const Eigen::Vector3d &x) {
  const Eigen::Matrix3d fd =
      ct::centralDifference([&](const Eigen::Vector3d &y) { return query(o, y).normal; }, x, 1e-6);
  EXPECT_LT((query(o, x).dNormal - fd).norm(), 1e-8) << "at " << x.transpose() << "\nanalytic\n"
                                                     << query(o, x).dNormal << "\nfinite differences\n"
                                                     << fd;
}

TEST(TriangulatedObstacle, OctahedronOnAFaceAnEdgeACornerAndInside) {
  const TriangulatedObstacle octa(ct::octahedron());
  const Eigen::Vector3d faceNormal = Eigen::Vector3d::Ones() / std::sqrt(3.0);
  // Face x + y + z = 1: the gap is the distance to the plane, the normal the plane's.
  ClosestPoint cp = query(octa, {0.5, 0.3, 0.4});
  EXPECT_NEAR(cp.gap, 0.2 / std::sqrt(3.0), 1e-15);
  EXPECT_LT((cp.normal - faceNormal).norm(), 1e-15);
  EXPECT_EQ(cp.dNormal, Eigen::Matrix3d::Zero());
  // Beyond the edge from (1, 0, 0) to (0, 1, 0), between its two faces' normals.
  const Eigen::Vector3d towardEdge = Eigen::Vector3d(1, 1, 0.2).normalized();
  cp = query(octa, Eigen::Vector3d(0.6, 0.4, 0) + 0.3 * towardEdge);
  EXPECT_NEAR(cp.gap, 0.3, 1e-15);
  EXPECT_LT((cp.point - Eigen::Vector3d(0.6, 0.4, 0)).norm(), 1e-15);
  EXPECT_LT((cp.normal - towardEdge).norm(), 1e-15);
  // Beyond the corner (1, 0, 0), inside the cone of its four edges.
  const Eigen::Vector3d towardCorner = Eigen::Vector3d(1, 0.2, -0.1).normalized();
  cp = query(octa, Eigen::Vector3d(1, 0, 0) + 0.5 * towardCorner);
  EXPECT_NEAR(cp.gap, 0.5, 1e-15);
  EXPECT_LT((cp.normal - towardCorner).norm(), 1e-15);
  // Inside: a negative gap, the distance to the nearest face plane.
  cp = query(octa, {0.1, 0.2, 0.1});
  EXPECT_NEAR(cp.gap, -0.6 / std::sqrt(3.0), 1e-15);
  EXPECT_LT((cp.point - Eigen::Vector3d(0.3, 0.4, 0.3)).norm(), 1e-15);
}

TEST(TriangulatedObstacle, BehindAnOpenSheetTheGapIsNegativeAndBesideItsFreeEdgePositive) {
  const TriangulatedObstacle sheet(ct::unitSquareSheet());  // z = 0, normals +z
  EXPECT_NEAR(query(sheet, {0.3, 0.6, -0.2}).gap, -0.2, 1e-15);
  // Past the free edge y = 0, below the sheet's plane: beside the sheet, not through it.
  const ClosestPoint cp = query(sheet, {0.5, -0.3, -0.2});
  EXPECT_NEAR(cp.gap, std::sqrt(0.13), 1e-15);
  EXPECT_LT((cp.normal - Eigen::Vector3d(0, -0.3, -0.2).normalized()).norm(), 1e-15);
  EXPECT_NEAR(query(sheet, {-0.2, -0.1, -0.3}).gap, std::sqrt(0.14), 1e-15);  // corner (0, 0, 0)
  EXPECT_NEAR(query(sheet, {1.2, 1.1, 0.3}).gap, std::sqrt(0.14), 1e-15);     // corner (1, 1, 0)
  // Under the inner edge of a valley the edge's pseudonormal signs the gap: behind, negative.
  const TriangulatedObstacle v(ct::valleySheet());
  const ClosestPoint under = query(v, {0, 0.5, -0.3});
  EXPECT_NEAR(under.gap, -0.3, 1e-15);
  EXPECT_LT((under.point - Eigen::Vector3d(0, 0.5, 0)).norm(), 1e-15);
  EXPECT_LT((under.normal - Eigen::Vector3d(0, 0, 1)).norm(), 1e-15);
}

TEST(TriangulatedObstacle, DNormalMatchesFiniteDifferencesOnFacesEdgesAndCorners) {
  const TriangulatedObstacle octa(ct::octahedron());
  expectDNormalMatchesFiniteDifferences(octa, {0.5, 0.3, 0.4});  // face: 0
  expectDNormalMatchesFiniteDifferences(
      octa, Eigen::Vector3d(0.6, 0.4, 0) + 0.3 * Eigen::Vector3d(1, 1, 0.2).normalized());
  expectDNormalMatchesFiniteDifferences(
      octa, Eigen::Vector3d(1, 0, 0) + 0.5 * Eigen::Vector3d(1, 0.2, -0.1).normalized());
  const TriangulatedObstacle sheet(ct::unitSquareSheet());
  expectDNormalMatchesFiniteDifferences(sheet, {0.5, -0.3, -0.2});   // beside the free edge
  expectDNormalMatchesFiniteDifferences(sheet, {-0.2, -0.1, -0.3});  // beside a free corner
  expectDNormalMatchesFiniteDifferences(sheet, {1.2, 1.1, 0.3});
  expectDNormalMatchesFiniteDifferences(TriangulatedObstacle(ct::valleySheet()),
                                        {0.05, 0.4, -0.3});  // inner edge, behind
}

TEST(TriangulatedObstacle, SearchRadiusLeavesOutWhatIsFarther) {
  const TriangulatedObstacle sheet(ct::unitSquareSheet());
  EXPECT_FALSE(sheet.closest({0.5, 0.5, 0.3}, 0.29).has_value());
  ASSERT_TRUE(sheet.closest({0.5, 0.5, 0.3}, 0.31).has_value());
  EXPECT_FALSE(sheet.closest({0.5, 0.5, -0.3}, 0.29).has_value());  // by distance, either side
  // Past the cube around the ball, and inside the cube but outside the ball.
  EXPECT_FALSE(sheet.closest({1.5, 1.5, 0.3}, 0.29).has_value());
  EXPECT_FALSE(sheet.closest({1.2, 1.2, 0}, 0.28).has_value());  // 0.283 away, in the cube of 0.28
  EXPECT_TRUE(sheet.closest({1.2, 1.2, 0}, 0.29).has_value());
  // A ball holding the whole surface finds it, from inside a closed one too.
  const TriangulatedObstacle octa(ct::octahedron());
  ASSERT_TRUE(octa.closest({0.1, 0.1, 0.1}, 100.0).has_value());
  EXPECT_NEAR(octa.closest({0.1, 0.1, 0.1}, 100.0)->gap, -0.7 / std::sqrt(3.0), 1e-15);
}

TEST(TriangulatedObstacle, TheTreeFindsWhatAScanOfEveryTriangleFinds) {
  const auto palate = glossa::contact::readObj(kTongue + "palate8.obj");
  const TriangulatedObstacle tree(palate);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> x(0.04, 0.16), y(-0.04, 0.04), z(0.03, 0.13);
  for (int k = 0; k < 300; ++k) {
    const Eigen::Vector3d p(x(rng), y(rng), z(rng));
    const ClosestPoint fromTree = query(tree, p);
    const ClosestPoint fromScan =
        glossa::contact::projectOnTriangle(palate, glossa::contact::closestTriangleByScan(palate, p), p);
    ASSERT_NEAR((p - fromTree.point).norm(), (p - fromScan.point).norm(), 1e-15);
    EXPECT_NEAR(fromTree.gap, fromScan.gap, 1e-15);
  }
}

// The README's figures are over the nodes of the hexahedron faces that belong to one element.
struct BoundaryNode {
  std::int64_t id;
  Eigen::Vector3d x;
};

std::vector<BoundaryNode> tongueBoundaryNodes() {
  const auto imported = glossa::mesh::readAnsysMesh(kTongue + "tongue.node", kTongue + "tongue.elem");
  std::set<glossa::mesh::NodeId> nodes;
  for (const auto &quad : glossa::mesh::testing::boundaryQuads(imported.mesh))
    nodes.insert(quad.begin(), quad.end());
  std::vector<BoundaryNode> out;
  for (auto n : nodes) out.push_back({imported.nodeFileIds[n], imported.mesh.nodes[n]});
  return out;
}

std::set<std::int64_t> idList(const std::string &file) {
  std::ifstream in(kTongue + file);
  std::set<std::int64_t> ids;
  for (std::int64_t id; in >> id;) ids.insert(id);
  return ids;
}

struct GapCensus {
  double smallest = kAnywhere;
  std::int64_t smallestAt = 0;
  std::map<std::int64_t, double> inside;  // node id -> gap < 0
  std::vector<double> gaps;
  int within(double d) const {
    return static_cast<int>(std::count_if(gaps.begin(), gaps.end(), [d](double g) { return g < d; }));
  }
};

GapCensus census(const std::string &file, const std::vector<BoundaryNode> &nodes) {
  const TriangulatedObstacle obstacle(glossa::contact::readObj(kTongue + file));
  GapCensus c;
  for (const BoundaryNode &n : nodes) {
    const double g = query(obstacle, n.x).gap;
    c.gaps.push_back(g);
    if (g < c.smallest) {
      c.smallest = g;
      c.smallestAt = n.id;
    }
    if (g < 0) c.inside[n.id] = g;
  }
  return c;
}

TEST(TriangulatedObstacle, TongueAtRestClearsThePalateAndTouchesTheBonesAsTheDataSays) {
  const std::vector<BoundaryNode> nodes = tongueBoundaryNodes();
  ASSERT_EQ(nodes.size(), 370u);
  const GapCensus palate = census("palate8.obj", nodes);
  EXPECT_NEAR(palate.smallest, 1.62e-3, 0.005e-3);
  EXPECT_EQ(palate.smallestAt, 578);
  EXPECT_TRUE(palate.inside.empty());
  EXPECT_EQ(palate.within(1e-3), 0);
  EXPECT_EQ(palate.within(2e-3), 1);
  EXPECT_EQ(palate.within(5e-3), 18);
  EXPECT_EQ(palate.within(10e-3), 70);

  const GapCensus jaw = census("ICPJaw3.obj", nodes);
  EXPECT_EQ(jaw.inside.size(), 10u);
  EXPECT_NEAR(jaw.smallest, -0.12e-3, 0.005e-3);
  const std::set<std::int64_t> attached = idList("jaw_attachment_nodes.txt");
  int insideAttached = 0;
  for (const auto &[id, gap] : jaw.inside) insideAttached += attached.count(id) ? 1 : 0;
  EXPECT_EQ(insideAttached, 8);
  for (std::int64_t id : {366, 779}) {
    ASSERT_TRUE(jaw.inside.count(id)) << "node " << id;
    EXPECT_NEAR(jaw.inside.at(id), -0.02e-3, 0.005e-3) << "node " << id;
  }
  EXPECT_EQ(jaw.within(1e-3), 138);
  EXPECT_EQ(jaw.within(2e-3), 165);
  EXPECT_EQ(jaw.within(5e-3), 209);

  const GapCensus hyoid = census("ICPHyoid3.obj", nodes);
  EXPECT_EQ(hyoid.inside.size(), 2u);
  EXPECT_TRUE(hyoid.inside.count(112) && hyoid.inside.count(525));
  EXPECT_GE(hyoid.smallest, -0.03e-3);
  EXPECT_EQ(hyoid.within(1e-3), 29);
  EXPECT_EQ(hyoid.within(2e-3), 44);
  EXPECT_EQ(hyoid.within(5e-3), 77);
}

}  // namespace
