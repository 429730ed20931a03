// Symmetry planes and the inside-out check: which conditions are planes, and how far material
// has crossed one, on a 2 x 1 x 1 box (0 <= X <= 2, 0 <= Y, Z <= 1).

#include <gtest/gtest.h>

#include <cmath>

#include "mesh/BoxGenerator.hpp"
#include "model/SymmetryPlanes.hpp"

namespace glossa::model {
namespace {

mesh::HexMesh box() { return mesh::generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d(2.0, 1.0, 1.0), {2, 1, 1}); }

DirichletCondition condition(const mesh::HexMesh &m, const std::string &set, int component, double value = 0.0) {
  DirichletCondition bc;
  bc.name = set;
  bc.nodes = m.nodeSets.at(set);
  bc.fixed[component] = true;
  bc.value[component] = value;
  return bc;
}

TEST(SymmetryPlanes, APlanarZeroConditionOnOneComponentIsAPlane) {
  const mesh::HexMesh m = box();
  std::vector<DirichletCondition> conditions = {condition(m, "xmin", 0), condition(m, "xmax", 0),
                                                condition(m, "ymin", 1, 1e-3), condition(m, "zmin", 0)};
  DirichletCondition clamp = condition(m, "zmax", 2);
  clamp.fixed = {true, true, true};
  conditions.push_back(clamp);
  const auto planes = findSymmetryPlanes(m, conditions);
  // xmin (x = 0, the body at x > 0) and xmax (x = 2, the body below it); not ymin (a nonzero
  // value), zmin (it fixes x, but its nodes do not lie on one plane of x), nor the clamp (three
  // components).
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].condition, 0u);
  EXPECT_EQ(planes[0].axis, 0);
  EXPECT_EQ(planes[0].position, 0.0);
  EXPECT_EQ(planes[0].side, 1.0);
  EXPECT_EQ(planes[1].condition, 1u);
  EXPECT_EQ(planes[1].position, 2.0);
  EXPECT_EQ(planes[1].side, -1.0);
}

TEST(SymmetryPlanes, AConditionInsideTheBodyIsNoPlane) {
  mesh::HexMesh m = box();
  // The nodes at x = 1 (the middle of the box) as a set: the body lies on both sides.
  for (std::size_t n = 0; n < m.numNodes(); ++n)
    if (m.nodes[n].x() == 1.0) m.nodeSets["middle"].push_back(static_cast<mesh::NodeId>(n));
  EXPECT_TRUE(findSymmetryPlanes(m, {condition(m, "middle", 0)}).empty());
}

TEST(SymmetryPlanes, MaterialAcrossThePlaneIsFoundWithItsDepth) {
  const mesh::HexMesh m = box();
  const auto planes = findSymmetryPlanes(m, {condition(m, "xmin", 0)});
  ASSERT_EQ(planes.size(), 1u);
  std::vector<double> u(3 * m.numNodes(), 0.0);
  EXPECT_EQ(deepestCrossing(planes, m, u).distance, 0.0); // the plane's own nodes
  // The body turned half a turn about the z axis, (X, Y) -> (-X, -Y): J = 1 everywhere, the
  // plane's nodes still on it, and the far end 2 across.
  for (std::size_t n = 0; n < m.numNodes(); ++n) u[3 * n] = -2.0 * m.nodes[n].x(), u[3 * n + 1] = -2.0 * m.nodes[n].y();
  const PlaneCrossing deepest = deepestCrossing(planes, m, u);
  EXPECT_DOUBLE_EQ(deepest.distance, -2.0);
  EXPECT_DOUBLE_EQ(m.nodes[deepest.node].x(), 2.0);
  EXPECT_EQ(deepest.plane, 0u);
  EXPECT_EQ(deepestCrossing({}, m, u).distance, std::numeric_limits<double>::infinity());
}

} // namespace
} // namespace glossa::model
