// The OBJ reader on small files written here (every corner form, negative indices, polygons,
// statements read past, scale) and on the real palate, mandible and hyoid of inputs/tongue/,
// whose triangle counts, boundary, area and volume the data's README gives.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "contact/ObjReader.hpp"
#include "contact/SurfaceFile.hpp"
#include "mesh/ImportTestSupport.hpp"

namespace {

using glossa::contact::readObj;
using glossa::contact::readSurface;
using glossa::contact::TriangleSurface;
using glossa::mesh::testing::expectError;
using glossa::mesh::testing::ScratchDir;

const std::string kTongue = std::string(GLOSSA_SOURCE_DIR) + "/inputs/tongue/";

TEST(ObjReader, ReadsEveryCornerFormNegativeIndicesAndPolygons) {
  ScratchDir dir("obj_forms");
  // A unit cube in millimetres: six quads written with each corner form, relative indices on
  // one face, comments and the statements a surface does not need.
  const std::string file = dir.write("cube.obj",
                                     "# a cube\r\n"
                                     "mtllib cube.mtl\n"
                                     "o cube\n"
                                     "v 0 0 0\nv 1000 0 0\nv 0 1000 0\nv 1000 1000 0\n"
                                     "v 0 0 1000\nv 1000 0 1000\nv 0 1000 1000\nv 1000 1000 1000  # last\n"
                                     "vt 0 0\nvt 1 0\nvn 0 0 1\n"
                                     "g sides\ns off\nusemtl bone\n"
                                     "f 1 3 4 2\n"
                                     "f 5/1 6/2 8/1 7/2\n"
                                     "f 1//1 2//1 6//1 5//1\n"
                                     "f 3/1/1 7/2/1 8/1/1 4/2/1\n"
                                     "f -8 -4 -2 -6\n"
                                     "f 2 4 8 6");
  const TriangleSurface s = readObj(file, 1e-3);
  EXPECT_EQ(s.vertices().size(), 8u);
  EXPECT_EQ(s.numTriangles(), 12u);
  EXPECT_TRUE(s.isClosed());
  EXPECT_NEAR(s.enclosedVolume(), 1.0, 1e-12);  // 1 m^3 once scaled, normals out
  EXPECT_EQ(s.vertices()[7], Eigen::Vector3d(1, 1, 1));
  EXPECT_EQ(s.source().where(11), file + ":23");  // the last face's second triangle
}

TEST(ObjReader, FanTriangulatesAPolygonWithTheWeightAndColourForms) {
  ScratchDir dir("obj_polygon");
  // A regular pentagon of circumradius 1 (weights divide, colours are ignored).
  std::ostringstream text;
  text.precision(17);
  for (int k = 0; k < 5; ++k) {
    const double a = 2 * M_PI * k / 5;
    if (k % 2)
      text << "v " << 2 * std::cos(a) << " " << 2 * std::sin(a) << " 0 2\n";
    else
      text << "v " << std::cos(a) << " " << std::sin(a) << " 0 0.5 0.5 0.5\n";
  }
  const TriangleSurface s = readObj(dir.write("pentagon.obj", text.str() + "f 1 2 3 4 5\n"));
  EXPECT_EQ(s.numTriangles(), 3u);
  EXPECT_NEAR(s.area(), 2.5 * std::sin(2 * M_PI / 5), 1e-14);  // (n/2) R^2 sin(2 pi / n)
  EXPECT_EQ(s.boundaryEdges(), 5u);
}

TEST(ObjReader, RefusesWhatItCannotReadNamingTheLine) {
  ScratchDir dir("obj_errors");
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expectError([&] { readObj(dir.write("a.obj", "v 0 0 0\nv 1 x 0\n")); },
              {"a.obj:2", "bad vertex coordinate 'x'"});
  expectError([&] { readObj(dir.write("b.obj", "v 0 0\n")); }, {"b.obj:1", "3 coordinates", "found 2"});
  expectError([&] { readObj(dir.write("c.obj", v + "f 1 2\n")); }, {"c.obj:4", "at least 3 corners"});
  expectError([&] { readObj(dir.write("d.obj", v + "f 1 0 2\n")); }, {"d.obj:4", "bad face corner '0'"});
  expectError([&] { readObj(dir.write("e.obj", v + "f 1/2/3/4 2 3\n")); }, {"e.obj:4", "'1/2/3/4'"});
  expectError([&] { readObj(dir.write("f.obj", v + "f -1 -2 -4\n")); }, {"f.obj:4", "'-4'", "3 read so far"});
  expectError([&] { readObj(dir.write("g.obj", v + "f 1 2 7\n")); },
              {"g.obj:4", "vertex 7", "vertices 1 to 3"});
  expectError([&] { readObj(dir.write("h.obj", v + "l 1 2\n")); }, {"h.obj:4", "unsupported statement 'l'"});
  expectError([&] { readObj(dir.write("i.obj", v)); }, {"i.obj", "no faces"});
  expectError([&] { readObj(dir.file("missing.obj")); }, {"missing.obj", "cannot open"});
  expectError([&] { readSurface(dir.write("j.ply", "ply\n")); }, {"j.ply", "'.ply'", ".obj, .stl"});
  EXPECT_THROW(readObj(dir.write("k.obj", v + "f 1 2 3\n"), 0.0), std::invalid_argument);
}

// The README of the surfaces (inputs/tongue/README.md) was measured with other tools: counts,
// boundary loop, area and enclosed volumes.
TEST(ObjReader, ReadsThePalateSheetAsAnOpenManifoldSurface) {
  const TriangleSurface palate = readSurface(kTongue + "palate8.obj");
  EXPECT_EQ(palate.vertices().size(), 3913u);
  EXPECT_EQ(palate.numTriangles(), 7596u);
  EXPECT_EQ(palate.boundaryEdges(), 228u);
  EXPECT_NEAR(palate.area(), 78.5e-4, 0.05e-4);
}

TEST(ObjReader, ReadsTheMandibleAndHyoidAsClosedSurfacesWithOutwardNormals) {
  const TriangleSurface jaw = readSurface(kTongue + "ICPJaw3.obj");
  EXPECT_EQ(jaw.vertices().size(), 1389u);
  EXPECT_EQ(jaw.numTriangles(), 2774u);  // 1384 quads and 6 triangles
  EXPECT_TRUE(jaw.isClosed());
  EXPECT_NEAR(jaw.enclosedVolume(), 93.2e-6, 0.05e-6);
  const TriangleSurface hyoid = readSurface(kTongue + "ICPHyoid3.obj");
  EXPECT_EQ(hyoid.vertices().size(), 330u);
  EXPECT_EQ(hyoid.numTriangles(), 656u);
  EXPECT_TRUE(hyoid.isClosed());
  EXPECT_NEAR(hyoid.enclosedVolume(), 3.4e-6, 0.05e-6);
}

}  // namespace
