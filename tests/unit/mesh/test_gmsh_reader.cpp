// The MSH 4.1 reader on meshes written by the gmsh binary (an independent producer) and on
// small hand-written files, malformed ones included.

#include <gtest/gtest.h>

#include <cstdlib>

#include "ImportTestSupport.hpp"
#include "MeshTestChecks.hpp"
#include "mesh/GmshReader.hpp"
#include "mesh/MeshQuality.hpp"

namespace glossa::mesh {
namespace {

using testing::expectError;
using testing::ScratchDir;

const std::string kBoxGeo = testing::gmshBoxGeo(true);

TEST(GmshReader, BoxWrittenByGmsh) {
  const std::string gmsh = GLOSSA_GMSH_EXECUTABLE;
  if (gmsh.empty()) GTEST_SKIP() << "gmsh binary not found at configure time";
  ScratchDir dir("gmsh_box");
  const std::string geo = dir.write("box.geo", kBoxGeo), msh = dir.file("box.msh");
  ASSERT_EQ(std::system((gmsh + " -3 " + geo + " -format msh41 -o " + msh + " > /dev/null 2>&1").c_str()), 0);
  const ImportedMesh imported = readGmsh(msh);
  const HexMesh &mesh = imported.mesh;
  EXPECT_EQ(mesh.numElements(), 32u);
  EXPECT_EQ(mesh.numNodes(), 75u);
  EXPECT_NEAR(meshVolume(mesh), 6.0, 1e-12);
  EXPECT_NEAR(testing::volumeByDivergence(mesh), 6.0, 1e-12);
  // Gmsh's hexahedron order is VTK's: every element right-handed, and a box cell is a box.
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    const auto X = mesh.elementCoordinates(static_cast<ElementId>(e));
    EXPECT_NEAR(minGaussPointJacobian(X), 0.5 * 0.5 * 0.75 / 8, 1e-12);
    EXPECT_NEAR(scaledJacobian(X), 1.0, 1e-12);
  }
  EXPECT_EQ(mesh.elementSets.at("body").size(), 32u);
  ASSERT_EQ(mesh.faceSets.at("bottom").size(), 8u);
  ASSERT_EQ(mesh.faceSets.at("top").size(), 8u);
  for (const ElementFace &f : mesh.faceSets.at("bottom")) EXPECT_NEAR(faceCentroid(mesh, f).z(), 0.0, 1e-12);
  for (const ElementFace &f : mesh.faceSets.at("top")) EXPECT_NEAR(faceCentroid(mesh, f).z(), 3.0, 1e-12);
  testing::expectOutwardNormals(mesh, "bottom");
  testing::expectOutwardNormals(mesh, "top");
  testing::expectNodeSetMatchesFaces(mesh, "bottom");
  EXPECT_EQ(mesh.nodeSets.at("bottom").size(), 15u);
  ASSERT_EQ(mesh.nodeSets.at("corner").size(), 1u);
  EXPECT_EQ(mesh.nodes[static_cast<std::size_t>(mesh.nodeSets.at("corner")[0])], Eigen::Vector3d::Zero());
}

// Two unit cubes stacked in z, node tags 11..22, hexahedron tags 100/200, quad 7 on the bottom
// (written clockwise seen from outside, as Gmsh's surface orientation may be), a point group
// without a name. `hex2` and `extra` let tests break it.
std::string twoCubes(const std::string &hex2 = "200 15 16 17 18 19 20 21 22",
                     const std::string &format = "4.1 0 8", const std::string &extra = "",
                     const std::string &endNodes = "$EndNodes") {
  return "$MeshFormat\r\n" + format +
         "\r\n$EndMeshFormat\r\n"
         "$PhysicalNames\r\n3\r\n3 1 \"muscle tissue\"\r\n2 2 \"floor\"\r\n3 5 "
         "\"upper\"\r\n$EndPhysicalNames\r\n"
         "$Entities\r\n1 0 1 2\r\n1 0 0 0 1 9\r\n"
         "1 0 0 0 1 1 0 1 2 0\r\n"
         "1 0 0 0 1 1 1 1 1 0\r\n2 0 0 1 1 1 2 2 1 5 0\r\n$EndEntities\r\n"
         "$Comments\r\nanything $here\r\n$EndComments\r\n"
         "$Nodes\r\n2 12 11 22\r\n3 1 0 8\r\n11\r\n12\r\n13\r\n14\r\n15\r\n16\r\n17\r\n18\r\n"
         "0 0 0\r\n1 0 0\r\n1 1 0\r\n0 1 0\r\n0 0 1\r\n1 0 1\r\n1 1 1\r\n0 1 1\r\n"
         "3 2 0 4\r\n19\r\n20\r\n21\r\n22\r\n0 0 2\r\n1 0 2\r\n1 1 2\r\n0 1 2\r\n" +
         endNodes + "\r\n$Elements\r\n4 4 1 200\r\n3 1 5 1\r\n100 11 12 13 14 15 16 17 18\r\n3 2 5 1\r\n" +
         hex2 + "\r\n2 1 3 1\r\n7 11 12 13 14\r\n0 1 15 1\r\n1 11\r\n" + extra + "$EndElements";
}

TEST(GmshReader, HandWrittenFile) {
  ScratchDir dir("gmsh_hand");
  const ImportedMesh imported = readGmsh(dir.write("two.msh", twoCubes()));
  const HexMesh &mesh = imported.mesh;
  EXPECT_EQ(mesh.numNodes(), 12u);
  EXPECT_EQ(mesh.numElements(), 2u);
  EXPECT_EQ(imported.nodeOfFileId(19), 8);
  EXPECT_EQ(imported.elementFileIds, (std::vector<std::int64_t>{100, 200}));
  EXPECT_EQ(mesh.elements[1], (Hex{4, 5, 6, 7, 8, 9, 10, 11}));
  // Volume entity 2 carries physical tags 1 and 5: its hexahedron is in both groups.
  EXPECT_EQ(mesh.elementSets.at("muscle tissue"), (std::vector<ElementId>{0, 1}));
  EXPECT_EQ(mesh.elementSets.at("upper"), std::vector<ElementId>{1});
  // Quad 11 12 13 14 is the bottom face (local face 0) of hexahedron 100.
  EXPECT_EQ(mesh.faceSets.at("floor"), (std::vector<ElementFace>{{0, 0}}));
  EXPECT_EQ(mesh.nodeSets.at("floor"), (std::vector<NodeId>{0, 1, 2, 3}));
  EXPECT_EQ(mesh.nodeSets.at("physical0d_9"), std::vector<NodeId>{0});
  EXPECT_NEAR(meshVolume(mesh), 2.0, 1e-14);
}

TEST(GmshReader, RefusesMalformedFiles) {
  ScratchDir dir("gmsh_bad");
  const std::string f = dir.file("bad.msh");
  auto read = [&](const std::string &text) {
    dir.write("bad.msh", text);
    return [f] { readGmsh(f); };
  };
  expectError(read(twoCubes("200 15 16 17 18 19 20 21 22", "4.0 0 8")), {f + ":2:", "MSH version 4.0"});
  // Binary by its header but ASCII after it: the endianness marker is the text "$End".
  expectError(read(twoCubes("200 15 16 17 18 19 20 21 22", "4.1 1 8")), {f + ": byte 22:", "endianness marker"});
  // A 4-node tetrahedron in a volume entity: refused, naming the type. The block header says
  // type 5, so give a tetrahedron a block of its own.
  const std::string tet = twoCubes();
  std::string withTet = tet;
  withTet.replace(withTet.find("4 4 1 200"), 9, "5 5 1 300");
  withTet.replace(withTet.find("$EndElements"), 12, "3 2 4 1\r\n300 15 16 17 19\r\n$EndElements");
  expectError(read(withTet), {f + ":59:", "volume entity 2 (physical 'muscle tissue', 'upper') contains tetrahedra "
                                          "(Gmsh type 4, 4-node tetrahedron): Glossa needs hexahedra",
                              "Recombine/Transfinite", "'Mesh.SubdivisionAlgorithm = 2;'"});
  expectError(read(twoCubes("200 15 16 17 18 19 20 21 99")), {f + ":", "refers to node 99"});
  expectError(read(twoCubes("200 15 16 17 18 19 20 21")), {f + ":", "needs 8 nodes, found 7"});
  expectError(read(twoCubes("200 19 20 21 22 15 16 17 18")), {f + ":", "element 200 is inverted"});
  expectError(read(twoCubes("100 15 16 17 18 19 20 21 22")), {f + ":", "duplicate element tag 100"});
  expectError(read(twoCubes("200 15 16 17 18 19 2x 21 22")), {f + ":", "bad node tag '2x'"});
  // Missing $EndNodes: the next header arrives where $EndNodes should be.
  expectError(read(twoCubes("200 15 16 17 18 19 20 21 22", "4.1 0 8", "", "")),
              {f + ":", "expected $EndNodes"});
  // Truncated file: ends inside $Elements.
  const std::string full = twoCubes();
  expectError(read(full.substr(0, full.find("$EndElements"))), {f + ":", "missing $EndElements"});
  expectError(read(full.substr(0, full.find("7 11 12 13 14"))), {f + ":", "file ends inside a section"});
  // A block announcing more nodes than it holds: the coordinates are met where tags should be.
  std::string miscount = full;
  miscount.replace(miscount.find("3 1 0 8"), 7, "3 1 0 9");
  expectError(read(miscount), {f + ":", "expected one node tag per line"});
  // A grouped quad that is no hexahedron face (a diagonal cut).
  std::string diagonal = full;
  diagonal.replace(diagonal.find("7 11 12 13 14"), 13, "7 11 13 19 17");
  expectError(read(diagonal), {f + ":", "quadrangle 7 of physical surface 'floor' is not a face"});
}

}  // namespace
}  // namespace glossa::mesh
