// TriangleSurface: normals, area, enclosed volume and boundary of shapes known in closed form,
// and the refusals (degenerate, non-manifold, inconsistently oriented), each naming the
// triangles, the vertices and where they are in the file.
#include <gtest/gtest.h>

#include <cmath>

#include "ContactTestSurfaces.hpp"
#include "contact/SurfaceError.hpp"
#include "mesh/ImportTestSupport.hpp"

namespace {

using glossa::contact::SurfaceError;
using glossa::contact::SurfaceSource;
using glossa::contact::TriangleSurface;
using glossa::mesh::testing::expectError;
namespace ct = glossa::contact::testing;

TEST(TriangleSurface, OctahedronIsClosedWithOutwardNormalsItsVolumeAndArea) {
  const TriangleSurface s = ct::octahedron();
  EXPECT_TRUE(s.isClosed());
  EXPECT_NEAR(s.enclosedVolume(), 4.0 / 3.0, 1e-14);     // 8 corner tetrahedra of volume 1/6
  EXPECT_NEAR(s.area(), 8 * std::sqrt(3.0) / 2, 1e-14);  // 8 equilateral triangles of side sqrt(2)
  for (std::size_t t = 0; t < s.numTriangles(); ++t) {
    const Eigen::Vector3d centroid = (s.corner(t, 0) + s.corner(t, 1) + s.corner(t, 2)) / 3;
    EXPECT_NEAR(s.normal(t).dot(centroid.normalized()), 1.0, 1e-14);  // out, through the face centre
  }
  const TriangleSurface f = s.flipped();
  EXPECT_NEAR(f.enclosedVolume(), -4.0 / 3.0, 1e-14);
  EXPECT_EQ(f.normal(3), -s.normal(3));
}

TEST(TriangleSurface, OpenSheetIsAllowedAndCountsItsBoundary) {
  const TriangleSurface s = ct::unitSquareSheet();
  EXPECT_FALSE(s.isClosed());
  EXPECT_EQ(s.boundaryEdges(), 4u);
  EXPECT_EQ(s.normal(0), Eigen::Vector3d(0, 0, 1));
  // An interior edge's pseudonormal is the sum of its two faces' normals; a boundary edge's the
  // face's own; a corner's the normal times the angles it spans (pi/2 at corner 1).
  EXPECT_EQ(s.edgePseudonormal(0, 2), Eigen::Vector3d(0, 0, 2));
  EXPECT_EQ(s.edgePseudonormal(0, 0), Eigen::Vector3d(0, 0, 1));
  EXPECT_NEAR(s.vertexPseudonormal(1).z(), M_PI / 2, 1e-14);
}

SurfaceSource lines(std::vector<std::size_t> l) { return {"shape.obj", false, std::move(l)}; }

TEST(TriangleSurface, RefusesDegenerateTriangles) {
  std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
  expectError(
      [&] {
        TriangleSurface(v, {{0, 1, 2}, {0, 1, 3}}, lines({7, 9}));
      },
      {"shape.obj:9", "triangle 2", "degenerate", "vertex 4 (2, 0, 0)"});
  expectError([&] { TriangleSurface(v, {{0, 1, 1}}, lines({3})); }, {"shape.obj:3", "degenerate"});
}

TEST(TriangleSurface, RefusesAnEdgeSharedByThreeTriangles) {
  std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  expectError(
      [&] {
        TriangleSurface(v, {{0, 1, 2}, {1, 0, 3}, {1, 0, 4}}, lines({4, 5, 6}));
      },
      {"shape.obj:6", "non-manifold", "vertex 1 (0, 0, 0)", "vertex 2 (1, 0, 0)", "shared by 3 triangles",
       "1 (shape.obj:4), 2 (shape.obj:5), 3 (shape.obj:6)"});
}

TEST(TriangleSurface, RefusesNeighboursThatRunTheirEdgeTheSameWay) {
  std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  // Triangle 2 runs 0 -> 1 as triangle 1 does: one of them is wound the wrong way.
  expectError(
      [&] {
        TriangleSurface(v, {{0, 1, 2}, {0, 1, 3}}, lines({10, 12}));
      },
      {"shape.obj:12", "inconsistent orientation", "triangles 1 (shape.obj:10) and 2", "vertex 1",
       "vertex 2"});
  // Wound the other way it is a valid open sheet.
  EXPECT_NO_THROW(TriangleSurface(v, {{0, 1, 2}, {1, 0, 3}}, lines({10, 12})));
}

TEST(TriangleSurface, RefusesVertexIndicesOutOfRangeAndAnEmptySurface) {
  std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  expectError(
      [&] {
        TriangleSurface(v, {{0, 1, 3}}, lines({2}));
      },
      {"shape.obj:2", "vertex 4", "vertices 1 to 3"});
  EXPECT_THROW(TriangleSurface(v, {}, lines({})), SurfaceError);
}

}  // namespace
