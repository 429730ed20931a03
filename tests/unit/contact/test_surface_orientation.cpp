// Choosing the normals' side: out of a closed surface by its enclosed volume, toward a point of
// the body for an open sheet; and the real palate, whose stored winding the README says faces
// the tongue, is kept as stored when a tongue point decides.
#include <gtest/gtest.h>

#include "ContactTestSurfaces.hpp"
#include "contact/ObjReader.hpp"
#include "contact/SurfaceOrientation.hpp"
#include "mesh/ImportTestSupport.hpp"

namespace {

using glossa::contact::NormalSide;
using glossa::contact::orientNormals;
using glossa::contact::TriangleSurface;
using glossa::mesh::testing::expectError;
namespace ct = glossa::contact::testing;

TEST(SurfaceOrientation, OutwardTurnsAnInwardClosedSurfaceOut) {
  const TriangleSurface inward = ct::octahedron().flipped();
  EXPECT_NEAR(orientNormals(inward, NormalSide::Outward).enclosedVolume(), 4.0 / 3.0, 1e-14);
  EXPECT_NEAR(orientNormals(ct::octahedron(), NormalSide::Outward).enclosedVolume(), 4.0 / 3.0, 1e-14);
  EXPECT_NEAR(orientNormals(inward, NormalSide::AsStored).enclosedVolume(), -4.0 / 3.0, 1e-14);
  expectError([] { orientNormals(ct::unitSquareSheet(), NormalSide::Outward); },
              {"sheet", "closed surface", "4 boundary edges", "point on the body's side"});
}

TEST(SurfaceOrientation, TowardPointFacesTheSheetToThePoint) {
  const TriangleSurface sheet = ct::unitSquareSheet();  // normals +z
  EXPECT_EQ(orientNormals(sheet, NormalSide::TowardPoint, {0.3, 0.6, 0.2}).normal(0),
            Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(orientNormals(sheet, NormalSide::TowardPoint, {0.3, 0.6, -0.2}).normal(0),
            Eigen::Vector3d(0, 0, -1));
  expectError(
      [&] {
        orientNormals(sheet, NormalSide::TowardPoint, {0.5, 0.5, 0});
      },
      {"sheet", "on the surface itself"});
  // Beyond the free edge a point faces neither side.
  expectError(
      [&] {
        orientNormals(sheet, NormalSide::TowardPoint, {-2, 3, -0.1});
      },
      {"sheet", "(-2, 3, -0.1)", "beside the surface's free edge"});
}

TEST(SurfaceOrientation, ThePalateFacesTheTongueAsStored) {
  const TriangleSurface palate =
      glossa::contact::readObj(std::string(GLOSSA_SOURCE_DIR) + "/inputs/tongue/palate8.obj");
  // Node 870 of tongue.node, the top of the dorsum.
  const TriangleSurface oriented =
      orientNormals(palate, NormalSide::TowardPoint, {0.09481132, 0.0, 0.113659});
  for (std::size_t t : {std::size_t(0), std::size_t(4000), palate.numTriangles() - 1}) {
    EXPECT_EQ(oriented.normal(t), palate.normal(t));
  }
}

}  // namespace
