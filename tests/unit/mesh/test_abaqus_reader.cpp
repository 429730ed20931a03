// The Abaqus reader on an .inp written by the gmsh binary (an independent producer) and on small
// hand-written files; the S1..S6 face mapping against the Abaqus manual's node lists.

#include <gtest/gtest.h>

#include <cstdlib>

#include "ImportTestSupport.hpp"
#include "MeshTestChecks.hpp"
#include "mesh/AbaqusReader.hpp"
#include "mesh/MeshQuality.hpp"

namespace glossa::mesh {
namespace {

using testing::expectError;
using testing::ScratchDir;

const std::string kBoxGeo = testing::gmshBoxGeo(false);

TEST(AbaqusReader, BoxWrittenByGmsh) {
  const std::string gmsh = GLOSSA_GMSH_EXECUTABLE;
  if (gmsh.empty()) GTEST_SKIP() << "gmsh binary not found at configure time";
  ScratchDir dir("abaqus_box");
  const std::string geo = dir.write("box.geo", kBoxGeo), inp = dir.file("box.inp");
  ASSERT_EQ(std::system((gmsh + " -3 " + geo + " -format inp -o " + inp + " > /dev/null 2>&1").c_str()), 0);
  const HexMesh mesh = readAbaqus(inp).mesh;
  EXPECT_EQ(mesh.numElements(), 32u);
  EXPECT_EQ(mesh.numNodes(), 75u);
  EXPECT_NEAR(meshVolume(mesh), 6.0, 1e-12);
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    EXPECT_NEAR(scaledJacobian(mesh.elementCoordinates(static_cast<ElementId>(e))), 1.0, 1e-12);
  }
  EXPECT_EQ(mesh.elementSets.at("body").size(), 32u);
  // Gmsh writes physical surfaces as ELSETs of CPS4 quadrilaterals: read as face sets.
  ASSERT_EQ(mesh.faceSets.at("bottom").size(), 8u);
  ASSERT_EQ(mesh.faceSets.at("top").size(), 8u);
  for (const ElementFace &f : mesh.faceSets.at("bottom")) EXPECT_NEAR(faceCentroid(mesh, f).z(), 0.0, 1e-12);
  for (const ElementFace &f : mesh.faceSets.at("top")) EXPECT_NEAR(faceCentroid(mesh, f).z(), 3.0, 1e-12);
  testing::expectOutwardNormals(mesh, "top");
  testing::expectNodeSetMatchesFaces(mesh, "top");
  EXPECT_EQ(mesh.nodeSets.at("top").size(), 15u);
}

// One unit cube, node ids 1..8 as in the Abaqus manual's C3D8 figure.
const std::string kCubeNodes =
    "*Node\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n5, 0, 0, 1\n6, 1., 0, 1\n7, 1, 1, 1\n8, 0, 1, "
    "1.0e0\n";

TEST(AbaqusReader, FaceNumberingFollowsTheManual) {
  ScratchDir dir("abaqus_faces");
  std::string text = "** one cube\n*HEADING\nface test\n" + kCubeNodes +
                     "*ELEMENT, TYPE=C3D8R, ELSET=cube\n1, 1, 2, 3, 4, 5, 6, 7, 8\n";
  for (int k = 1; k <= 6; ++k) {
    text += "*Surface, type=ELEMENT, name=s" + std::to_string(k) + "\ncube, S" + std::to_string(k) + "\n";
  }
  const HexMesh mesh = readAbaqus(dir.write("cube.inp", text)).mesh;
  // Abaqus Analysis User's Guide, "Three-dimensional solid element library", C3D8 faces.
  const std::vector<std::vector<NodeId>> manual = {{1, 2, 3, 4}, {5, 8, 7, 6}, {1, 5, 6, 2},
                                                   {2, 6, 7, 3}, {3, 7, 8, 4}, {4, 8, 5, 1}};
  const Eigen::Vector3d centroids[6] = {{0.5, 0.5, 0}, {0.5, 0.5, 1}, {0.5, 0, 0.5},
                                        {1, 0.5, 0.5}, {0.5, 1, 0.5}, {0, 0.5, 0.5}};
  for (int k = 0; k < 6; ++k) {
    const std::string name = "s" + std::to_string(k + 1);
    ASSERT_EQ(mesh.faceSets.at(name).size(), 1u);
    EXPECT_EQ(mesh.faceSets.at(name)[0].localFace, k);
    EXPECT_NEAR((faceCentroid(mesh, mesh.faceSets.at(name)[0]) - centroids[k]).norm(), 0, 1e-15) << name;
    std::vector<NodeId> expected;
    for (NodeId n : manual[static_cast<std::size_t>(k)]) expected.push_back(n - 1);
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(mesh.nodeSets.at(name), expected) << name;
    testing::expectOutwardNormals(mesh, name);
  }
}

// Two cubes stacked in z, with the syntax variants a careful reader must accept.
std::string twoCubes(const std::string &second = "2, 5, 6, 7, 8,\n 9, 10, 11, 12\n",
                     const std::string &extra = "") {
  return "**comment\n" + kCubeNodes +
         "*node, nset=TOPNODES\n9, 0, 0, 2\n10, 1, 0, 2\n11, 1, 1, 2\n12, 0, 1, 2\n"
         "*Element, type=C3D8H,\n elset=LOWER\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
         "*ELEMENT, TYPE=C3D8, ELSET=Upper\n" +
         second +
         "*ELEMENT, TYPE=S4R, ELSET=floor\n20, 1, 4, 3, 2\n"
         "*ELSET, ELSET=all, generate\n1, 2, 1\n*Elset, elset=copy\nlower,\n"
         "*NSET, NSET=bottom, GENERATE\n1, 4\n*NSET, NSET=evens\n2, 4, 6,\n8\n"
         "*SURFACE, NAME=side\n2, S4\nlower, s4\n*MATERIAL, NAME=x\n*ELASTIC\n1e3, 0.3\n" +
         extra;
}

TEST(AbaqusReader, HandWrittenFile) {
  ScratchDir dir("abaqus_hand");
  const ImportedMesh imported = readAbaqus(dir.write("two.inp", twoCubes()));
  const HexMesh &mesh = imported.mesh;
  EXPECT_EQ(mesh.numNodes(), 12u);
  EXPECT_EQ(mesh.numElements(), 2u);  // the S4R quadrilateral is no volume element
  EXPECT_EQ(imported.elementFileIds, (std::vector<std::int64_t>{1, 2}));
  EXPECT_EQ(mesh.elements[1], (Hex{4, 5, 6, 7, 8, 9, 10, 11}));
  EXPECT_EQ(mesh.elementSets.at("LOWER"), std::vector<ElementId>{0});
  EXPECT_EQ(mesh.elementSets.at("Upper"), std::vector<ElementId>{1});
  EXPECT_EQ(mesh.elementSets.at("all"), (std::vector<ElementId>{0, 1}));
  EXPECT_EQ(mesh.elementSets.at("copy"), std::vector<ElementId>{0});
  EXPECT_EQ(mesh.faceSets.at("floor"), (std::vector<ElementFace>{{0, 0}}));
  EXPECT_EQ(mesh.nodeSets.at("floor"), (std::vector<NodeId>{0, 1, 2, 3}));
  EXPECT_EQ(mesh.faceSets.at("side"), (std::vector<ElementFace>{{0, 3}, {1, 3}}));
  for (const ElementFace &f : mesh.faceSets.at("side")) EXPECT_NEAR(faceCentroid(mesh, f).x(), 1.0, 1e-15);
  EXPECT_EQ(mesh.nodeSets.at("bottom"), (std::vector<NodeId>{0, 1, 2, 3}));
  EXPECT_EQ(mesh.nodeSets.at("evens"), (std::vector<NodeId>{1, 3, 5, 7}));
  EXPECT_EQ(mesh.nodeSets.at("TOPNODES"), (std::vector<NodeId>{8, 9, 10, 11}));
  EXPECT_NEAR(meshVolume(mesh), 2.0, 1e-15);
}

// Gmsh exports a physical curve as T3D2 lines in an ELSET: the node set of their nodes (an NSET of
// the same name, as for face sets, would take precedence).
TEST(AbaqusReader, LineElsetsAreNodeSets) {
  ScratchDir dir("abaqus_lines");
  const std::string extra = "*ELEMENT, type=T3D2, ELSET=Line1\n30, 1, 2\n31, 2, 6\n*ELSET,ELSET=edge\n30, 31,\n";
  const HexMesh mesh = readAbaqus(dir.write("two.inp", twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", extra))).mesh;
  EXPECT_EQ(mesh.numElements(), 2u);
  EXPECT_EQ(mesh.nodeSets.at("edge"), (std::vector<NodeId>{0, 1, 5}));
  EXPECT_EQ(mesh.nodeSets.at("Line1"), (std::vector<NodeId>{0, 1, 5}));
  EXPECT_EQ(mesh.elementSets.count("edge"), 0u);
  EXPECT_EQ(mesh.faceSets.count("edge"), 0u);
  const std::string f = dir.write("bad.inp", twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", extra + "*ELSET, ELSET=odd\n1, 30\n"));
  expectError([&] { readAbaqus(f); }, {f + ":", "'odd' mixes hexahedra, quadrilaterals and lines"});
}

TEST(AbaqusReader, RefusesMalformedFiles) {
  ScratchDir dir("abaqus_bad");
  const std::string f = dir.file("bad.inp");
  auto read = [&](const std::string &text) {
    dir.write("bad.inp", text);
    return [f] { readAbaqus(f); };
  };
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 99\n")), {f + ":20:", "element 2 refers to node 99"});
  expectError(read(twoCubes("2, 9, 10, 11, 12, 5, 6, 7, 8\n")), {f + ":20:", "element 2 is inverted"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 9\n")), {f + ":20:", "element 2 repeats a node"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11\n")), {f + ":20:", "element 2 is truncated"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12, 13\n")), {f + ":20:", "needs 8 nodes, found 9"});
  expectError(read(twoCubes("1, 5, 6, 7, 8, 9, 10, 11, 12\n")), {f + ":20:", "duplicate element id 1"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 1x\n")), {f + ":20:", "bad node id '1x'"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*ELEMENT, TYPE=C3D4\n3, 1, 2, 3, 5\n")),
              {f + ":38:", "element type C3D4 is not supported", "C3D4 are tetrahedra: Glossa needs hexahedra",
               "Mesh.SubdivisionAlgorithm = 2"});
  // Each refused kind with its remedy, as the MSH reader gives one.
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*ELEMENT, TYPE=CPS3\n3, 1, 2, 3\n")),
              {f + ":38:", "CPS3 are triangles", "'Recombine Surface'"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*ELEMENT, TYPE=C3D20R\n3, 1, 2, 3\n")),
              {f + ":38:", "C3D20R are second-order hexahedra", "Mesh.ElementOrder = 1"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*ELEMENT, TYPE=S8R\n3, 1, 2, 3\n")),
              {f + ":38:", "S8R are second-order quadrilaterals"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*ELEMENT, TYPE=C3D6\n3, 1, 2, 3\n")),
              {f + ":38:", "C3D6 are prisms"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*ELEMENT, TYPE=C3D99999999999\n3, 1\n")),
              {f + ":38:", "element type C3D99999999999 is not supported: Glossa reads"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*SURFACE, NAME=s\nnosuchset, S1\n")),
              {f + ":39:", "unknown element set 'nosuchset'"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*ELSET, ELSET=x\n1, missing\n")),
              {f + ":39:", "unknown element set 'missing'"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*SURFACE, NAME=s\n1, S7\n")),
              {f + ":39:", "'S7' is not S1..S6"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*ELSET, ELSET=mixed\n1, 20\n")),
              {f + ":38:", "'mixed' mixes hexahedra, quadrilaterals and lines"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*ELSET, ELSET=far\n1, 77\n")),
              {f + ":38:", "refers to element 77"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*INCLUDE, INPUT=more.inp\n")),
              {f + ":38:", "*INCLUDE is not supported"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*NODE\n3, 0, 0, 0\n")),
              {f + ":39:", "duplicate node id 3"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*NODE\n30, 0, 0\n")),
              {f + ":39:", "expected 'id, x, y, z'"});
  // A GENERATE range past the ids defined (the fuzz test's '1, 2147483648' filled memory).
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*NSET, NSET=huge, GENERATE\n1, 2147483648\n")),
              {f + ":39:", "GENERATE range 1 to 2147483648 reaches past the largest node id defined above it (12)"});
  expectError(read(twoCubes("2, 5, 6, 7, 8, 9, 10, 11, 12\n", "*ELSET, ELSET=huge, GENERATE\n1, 99\n")),
              {f + ":39:", "reaches past the largest element id defined above it (20)"});
  expectError(read("1, 2, 3\n"), {f + ":1:", "data line before any keyword"});
  expectError(read(kCubeNodes), {f + ":", "no hexahedral elements"});
}

}  // namespace
}  // namespace glossa::mesh
