// The STL reader: ASCII and binary files written here byte by byte (a binary header that starts
// with "solid" included), corners merged into shared vertices, scale, and the errors with their
// line or byte offset; and the palate written as binary STL reads back as the OBJ did.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>

#include "ContactTestSurfaces.hpp"
#include "contact/ObjReader.hpp"
#include "contact/StlReader.hpp"
#include "contact/SurfaceFile.hpp"
#include "mesh/ImportTestSupport.hpp"

namespace {

using glossa::contact::readStl;
using glossa::contact::readSurface;
using glossa::contact::TriangleSurface;
using glossa::mesh::testing::expectError;
using glossa::mesh::testing::ScratchDir;
namespace ct = glossa::contact::testing;

std::string asciiStl(const TriangleSurface &s, double unit) {
  std::ostringstream out;
  out.precision(17);
  out << "solid shape\n";
  for (std::size_t t = 0; t < s.numTriangles(); ++t) {
    out << "  facet normal 0 0 0\n    outer loop\n";
    for (int k = 0; k < 3; ++k) out << "      vertex " << s.corner(t, k).transpose() / unit << "\n";
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid shape\n";
  return out.str();
}

void put32(std::string &b, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) b += static_cast<char>((v >> (8 * k)) & 0xff);  // little endian
}
void putFloat(std::string &b, float f) {
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  put32(b, bits);
}

std::string binaryStl(const TriangleSurface &s, const std::string &header) {
  std::string b = header;
  b.resize(80, ' ');
  put32(b, static_cast<std::uint32_t>(s.numTriangles()));
  for (std::size_t t = 0; t < s.numTriangles(); ++t) {
    for (int d = 0; d < 3; ++d) putFloat(b, static_cast<float>(s.normal(t)[d]));
    for (int k = 0; k < 3; ++k) {
      for (int d = 0; d < 3; ++d) putFloat(b, static_cast<float>(s.corner(t, k)[d]));
    }
    b += std::string(2, '\0');  // attribute byte count
  }
  return b;
}

TEST(StlReader, ReadsAsciiMergingCornersIntoVerticesAndScales) {
  ScratchDir dir("stl_ascii");
  const TriangleSurface cube = ct::unitCube();
  const TriangleSurface s = readStl(dir.write("cube.stl", asciiStl(cube, 1e-3)), 1e-3);  // written in mm
  EXPECT_EQ(s.numTriangles(), 12u);
  EXPECT_EQ(s.vertices().size(), 8u);  // 36 corners, 8 distinct points
  EXPECT_TRUE(s.isClosed());
  EXPECT_NEAR(s.enclosedVolume(), 1.0, 1e-12);
  EXPECT_EQ(s.source().where(1), s.source().file + ":9");  // the second facet's line
}

TEST(StlReader, TellsBinaryBySizeEvenWhenTheHeaderStartsWithSolid) {
  ScratchDir dir("stl_binary");
  const TriangleSurface octa = ct::octahedron();
  for (const std::string header : {"solid exported by a CAD program", "binary"}) {
    const TriangleSurface s = readSurface(dir.write("octa.STL", binaryStl(octa, header)));
    EXPECT_EQ(s.numTriangles(), 8u);
    EXPECT_EQ(s.vertices().size(), 6u);
    EXPECT_NEAR(s.enclosedVolume(), 4.0 / 3.0, 1e-7);  // float coordinates
    EXPECT_EQ(s.source().where(2), s.source().file + ": byte " + std::to_string(84 + 2 * 50));
  }
}

TEST(StlReader, RefusesBadAsciiNamingTheLine) {
  ScratchDir dir("stl_ascii_errors");
  const std::string head = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n";
  expectError([&] { readStl(dir.write("a.stl", head + "vertex 0 1\n")); }, {"a.stl:6", "3 coordinates"});
  expectError([&] { readStl(dir.write("b.stl", head + "vertex 0 1 z\n")); },
              {"b.stl:6", "bad coordinate 'z'"});
  expectError([&] { readStl(dir.write("c.stl", head + "vertex 0 1 0\nvertex 1 1 0\n")); },
              {"c.stl:7", "'endloop' (a facet has 3 vertices, not more)"});
  expectError([&] { readStl(dir.write("d.stl", head + "vertex 0 1 0\nendloop\nendfacet\n")); },
              {"d.stl:9", "no 'endsolid'"});
  expectError([&] { readStl(dir.write("e.stl", "solid s\nfacet 0 0 1\n")); },
              {"e.stl:2", "'facet normal nx ny nz'"});
  expectError([&] { readStl(dir.write("f.stl", "solid s\nendsolid s\n")); }, {"f.stl", "no facets"});
  // The same edge run twice the same way: the orientation check names the facets' lines.
  const std::string facet =
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  const std::string other =
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 -1 0\nendloop\nendfacet\n";
  expectError([&] { readStl(dir.write("g.stl", "solid s\n" + facet + other + "endsolid\n")); },
              {"g.stl:9", "inconsistent orientation", "g.stl:2)"});
}

TEST(StlReader, RefusesBadBinaryNamingTheSizeOrTheByte) {
  ScratchDir dir("stl_binary_errors");
  std::string bytes = binaryStl(ct::octahedron(), "binary");
  expectError([&] { readStl(dir.write("short.stl", bytes.substr(0, bytes.size() - 1))); },
              {"short.stl", "does not start with 'solid'", "8 (bytes 80-83)",
               std::to_string(bytes.size() - 1) + " bytes"});
  expectError([&] { readStl(dir.write("solid.stl", binaryStl(ct::octahedron(), "solid").substr(0, 100))); },
              {"solid.stl", "NUL bytes"});
  // A NaN as the y of triangle 3's second corner.
  const std::size_t at = 84 + 2 * 50 + 12 + 12 + 4;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&bytes[at], &nan, 4);
  expectError([&] { readStl(dir.write("nan.stl", bytes)); },
              {"nan.stl: byte " + std::to_string(at), "triangle 3"});
  expectError([&] { readStl(dir.write("tiny.stl", "abc")); }, {"tiny.stl", "3 bytes"});
}

TEST(StlReader, ThePalateAsBinaryStlReadsBackAsTheObj) {
  ScratchDir dir("stl_palate");
  const TriangleSurface obj =
      glossa::contact::readObj(std::string(GLOSSA_SOURCE_DIR) + "/inputs/tongue/palate8.obj");
  const TriangleSurface stl = readStl(dir.write("palate.stl", binaryStl(obj, "palate")));
  EXPECT_EQ(stl.numTriangles(), obj.numTriangles());
  EXPECT_EQ(stl.vertices().size(), obj.vertices().size());  // every shared corner merged again
  EXPECT_EQ(stl.boundaryEdges(), obj.boundaryEdges());
  EXPECT_NEAR(stl.area(), obj.area(), 1e-6 * obj.area());  // float rounding of the coordinates
}

}  // namespace
