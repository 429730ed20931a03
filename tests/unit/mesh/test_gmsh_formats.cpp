// The MSH encodings besides 4.1 ASCII on small hand-made files: 2.2 ASCII, 2.2 binary and 4.1
// binary hold the same two stacked cubes as test_gmsh_reader.cpp's twoCubes() and must give the
// same mesh and sets; binary files are written byte by byte here in the layout of the Gmsh
// manual, so a layout slip in the reader cannot be mirrored by a writer. Then the refusals
// (truncated and corrupted binary data, a big-endian marker, tetrahedra and other non-hexahedra
// by name) and second-order elements read by their corners.

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>

#include "ImportTestSupport.hpp"
#include "mesh/GmshReader.hpp"
#include "mesh/MeshChecks.hpp"
#include "mesh/MeshError.hpp"
#include "mesh/MeshQuality.hpp"

namespace glossa::mesh {
namespace {

using testing::expectError;
using testing::ScratchDir;

// Binary data as the Gmsh manual lays it out (little-endian, as on the machines Gmsh and
// Glossa run on).
class Bytes {
 public:
  Bytes &text(const std::string &s) {
    data_ += s;
    return *this;
  }
  Bytes &i32(std::int32_t v) { return raw(&v, 4); }
  Bytes &u64(std::uint64_t v) { return raw(&v, 8); }
  Bytes &f64(double v) { return raw(&v, 8); }
  const std::string &str() const { return data_; }
  std::size_t size() const { return data_.size(); }

 private:
  Bytes &raw(const void *p, std::size_t n) {
    data_.append(static_cast<const char *>(p), n);
    return *this;
  }
  std::string data_;
};

// The two cubes: nodes 11..22 at these positions, hexahedra 100 (11..18) and 200 (15..22).
const double kX[12][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
                          {1, 1, 1}, {0, 1, 1}, {0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}};
const std::string kNames =
    "$PhysicalNames\n3\n3 1 \"muscle tissue\"\n2 2 \"floor\"\n3 5 \"upper\"\n$EndPhysicalNames\n";

// What every encoding of the two cubes must read as (test_gmsh_reader.cpp's HandWrittenFile).
void expectTwoCubes(const ImportedMesh &imported) {
  const HexMesh &mesh = imported.mesh;
  ASSERT_EQ(mesh.numNodes(), 12u);
  ASSERT_EQ(mesh.numElements(), 2u);
  for (int n = 0; n < 12; ++n) {
    EXPECT_EQ(imported.nodeOfFileId(11 + n), n);
    EXPECT_EQ(mesh.nodes[static_cast<std::size_t>(n)], Eigen::Vector3d(kX[n][0], kX[n][1], kX[n][2]));
  }
  EXPECT_EQ(imported.elementFileIds, (std::vector<std::int64_t>{100, 200}));
  EXPECT_EQ(mesh.elements[0], (Hex{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(mesh.elements[1], (Hex{4, 5, 6, 7, 8, 9, 10, 11}));
  EXPECT_EQ(mesh.elementSets.size(), 2u);
  EXPECT_EQ(mesh.elementSets.at("muscle tissue"), (std::vector<ElementId>{0, 1}));
  EXPECT_EQ(mesh.elementSets.at("upper"), std::vector<ElementId>{1});
  EXPECT_EQ(mesh.faceSets.size(), 1u);
  EXPECT_EQ(mesh.faceSets.at("floor"), (std::vector<ElementFace>{{0, 0}}));
  EXPECT_EQ(mesh.nodeSets.size(), 2u);
  EXPECT_EQ(mesh.nodeSets.at("floor"), (std::vector<NodeId>{0, 1, 2, 3}));
  EXPECT_EQ(mesh.nodeSets.at("physical0d_9"), std::vector<NodeId>{0});
  EXPECT_TRUE(imported.notes.empty());
  EXPECT_NEAR(meshVolume(mesh), 2.0, 1e-14);
}

std::string hexNodes(int first) {
  std::string s;
  for (int a = 0; a < 8; ++a) s += " " + std::to_string(first + a);
  return s;
}

// MSH 2.2 ASCII. Hexahedron 200 is in two groups, so it is written twice (tags 200 and 201),
// as Gmsh's MSH 2 writer does; `extraElements` are appended (and counted).
std::string twoCubes22(const std::vector<std::string> &extraElements = {}) {
  std::string s = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" + kNames + "$Nodes\n12\n";
  for (int n = 0; n < 12; ++n) {
    s += std::to_string(11 + n) + " " + std::to_string(kX[n][0]) + " " + std::to_string(kX[n][1]) + " " +
         std::to_string(kX[n][2]) + "\n";
  }
  s += "$EndNodes\n$Elements\n" + std::to_string(5 + extraElements.size()) +
       "\n1 15 2 9 1 11\n7 3 2 2 1 11 12 13 14\n100 5 2 1 1" + hexNodes(11) + "\n200 5 2 1 2" + hexNodes(15) +
       "\n201 5 2 5 2" + hexNodes(15) + "\n";
  for (const auto &e : extraElements) s += e + "\n";
  return s + "$EndElements\n";
}

TEST(GmshFormats, Msh22Ascii) {
  ScratchDir dir("gmsh22a");
  const ImportedMesh imported = readGmsh(dir.write("two.msh", twoCubes22()));
  expectTwoCubes(imported);
  // The copy's tag names no element of its own: it is element 200 in a second group.
  EXPECT_FALSE(imported.hasElementFileId(201));
}

// Gmsh's MSH 2 writer with -save_all writes physical tag 0 on every element: no sets, and a note
// saying why (the names are there, the groups are not).
TEST(GmshFormats, Msh22WithoutPhysicalTagsNotesIt) {
  ScratchDir dir("gmsh22_saveall");
  std::string text = twoCubes22();
  const std::size_t elements = text.find("$Elements");
  text = text.substr(0, elements) + "$Elements\n2\n100 5 2 0 1" + hexNodes(11) + "\n200 5 2 0 2" +
         hexNodes(15) + "\n$EndElements\n";
  const std::string f = dir.write("all.msh", text);
  const ImportedMesh imported = readGmsh(f);
  EXPECT_EQ(imported.mesh.numElements(), 2u);
  EXPECT_TRUE(imported.mesh.elementSets.empty());
  EXPECT_TRUE(imported.mesh.faceSets.empty());
  ASSERT_EQ(imported.notes.size(), 1u);
  EXPECT_EQ(
      imported.notes[0].rfind(f + ": $PhysicalNames names groups but no element carries a physical tag", 0),
      0u)
      << imported.notes[0];
}

std::string header(const std::string &version) {
  return "$MeshFormat\n" + version + " 1 8\n" + std::string("\x01\x00\x00\x00", 4) + "\n$EndMeshFormat\n";
}

// MSH 2.2 binary: the nodes as int id + 3 doubles, the elements in blocks (type, count, ntags)
// of int id, tags, nodes. Hexahedra 100 and 200 share a block; the copy 201 has its own.
Bytes twoCubes22Binary() {
  Bytes b;
  b.text(header("2.2") + kNames + "$Nodes\n12\n");
  for (int n = 0; n < 12; ++n) b.i32(11 + n).f64(kX[n][0]).f64(kX[n][1]).f64(kX[n][2]);
  b.text("\n$EndNodes\n$Elements\n5\n");
  b.i32(15).i32(1).i32(2).i32(1).i32(9).i32(1).i32(11);
  b.i32(3).i32(1).i32(2).i32(7).i32(2).i32(1).i32(11).i32(12).i32(13).i32(14);
  b.i32(5).i32(2).i32(2);
  b.i32(100).i32(1).i32(1);
  for (int a = 0; a < 8; ++a) b.i32(11 + a);
  b.i32(200).i32(1).i32(2);
  for (int a = 0; a < 8; ++a) b.i32(15 + a);
  b.i32(5).i32(1).i32(2).i32(201).i32(5).i32(2);
  for (int a = 0; a < 8; ++a) b.i32(15 + a);
  b.text("\n$EndElements\n");
  return b;
}

TEST(GmshFormats, Msh22Binary) {
  ScratchDir dir("gmsh22b");
  expectTwoCubes(readGmsh(dir.write("two.msh", twoCubes22Binary().str())));
}

// Where twoCubes41Binary() put things, for tests that break them.
struct Layout41 {
  std::size_t firstNodeBlock = 0, secondNodeCoordinates = 0, elementsHeader = 0;
};

// MSH 4.1 binary. Entities: point 1 (physical 9), surface 1 (physical 2, bounded by curves 1 and
// -2, which the reader steps over), volumes 1 (physical 1) and 2 (physicals 1 and 5). Nodes:
// 11..18 in volume 1; 19..22 in surface 1 with parametric coordinates (u, v after x y z).
Bytes twoCubes41Binary(Layout41 *layout = nullptr) {
  Bytes b;
  b.text(header("4.1") + kNames + "$Entities\n");
  b.u64(1).u64(0).u64(1).u64(2);
  b.i32(1).f64(0).f64(0).f64(0).u64(1).i32(9);
  b.i32(1).f64(0).f64(0).f64(0).f64(1).f64(1).f64(0).u64(1).i32(2).u64(2).i32(1).i32(-2);
  b.i32(1).f64(0).f64(0).f64(0).f64(1).f64(1).f64(1).u64(1).i32(1).u64(0);
  b.i32(2).f64(0).f64(0).f64(1).f64(1).f64(1).f64(2).u64(2).i32(1).i32(5).u64(1).i32(1);
  b.text("\n$EndEntities\n$Nodes\n");
  b.u64(2).u64(12).u64(11).u64(22);
  if (layout) layout->firstNodeBlock = b.size();
  b.i32(3).i32(1).i32(0).u64(8);
  for (int n = 0; n < 8; ++n) b.u64(11 + n);
  for (int n = 0; n < 8; ++n) b.f64(kX[n][0]).f64(kX[n][1]).f64(kX[n][2]);
  b.i32(2).i32(1).i32(1).u64(4);
  for (int n = 8; n < 12; ++n) b.u64(11 + n);
  if (layout) layout->secondNodeCoordinates = b.size();
  for (int n = 8; n < 12; ++n) b.f64(kX[n][0]).f64(kX[n][1]).f64(kX[n][2]).f64(0.25 * n).f64(0.5);
  b.text("\n$EndNodes\n$Elements\n");
  if (layout) layout->elementsHeader = b.size();
  b.u64(4).u64(4).u64(1).u64(200);
  b.i32(3).i32(1).i32(5).u64(1).u64(100);
  for (int a = 0; a < 8; ++a) b.u64(11 + a);
  b.i32(3).i32(2).i32(5).u64(1).u64(200);
  for (int a = 0; a < 8; ++a) b.u64(15 + a);
  b.i32(2).i32(1).i32(3).u64(1).u64(7).u64(11).u64(12).u64(13).u64(14);
  b.i32(0).i32(1).i32(15).u64(1).u64(1).u64(11);
  b.text("\n$EndElements\n");
  return b;
}

TEST(GmshFormats, Msh41Binary) {
  ScratchDir dir("gmsh41b");
  expectTwoCubes(readGmsh(dir.write("two.msh", twoCubes41Binary().str())));
}

template <typename T>
void put(std::string &data, std::size_t at, T value) {
  std::memcpy(&data[at], &value, sizeof value);
}

TEST(GmshFormats, RefusesBrokenBinaryFiles) {
  ScratchDir dir("gmsh_bad_binary");
  const std::string f = dir.file("bad.msh");
  auto read = [&](const std::string &bytes) {
    dir.write("bad.msh", bytes);
    return [f] { readGmsh(f); };
  };
  Layout41 at;
  const std::string good = twoCubes41Binary(&at).str();
  const std::size_t marker = header("4.1").find('\x01');
  // Big-endian marker, and one that is no marker at all.
  std::string bigEndian = good;
  bigEndian.replace(marker, 4, std::string("\x00\x00\x00\x01", 4));
  expectError(read(bigEndian), {f + ": byte " + std::to_string(marker) + ":", "written big-endian"});
  std::string noMarker = good;
  put<std::int32_t>(noMarker, marker, 7);
  expectError(read(noMarker), {f + ": byte " + std::to_string(marker) + ":", "bad endianness marker 7"});
  // Truncated inside the second node block's coordinates: the block's need is checked first.
  expectError(read(good.substr(0, at.secondNodeCoordinates + 20)),
              {f + ": byte " + std::to_string(at.secondNodeCoordinates - 32) + ":",
               "file ends inside a node block of 4 nodes"});
  // A node count of 2^40 is refused against the bytes left, before any allocation.
  std::string huge = good;
  put<std::uint64_t>(huge, at.firstNodeBlock + 12, std::uint64_t(1) << 40);
  expectError(read(huge), {f + ": byte " + std::to_string(at.firstNodeBlock + 20) + ":",
                           "1099511627776 x 32 bytes announced"});
  // An element total that disagrees with the blocks.
  std::string total = good;
  put<std::uint64_t>(total, at.elementsHeader + 8, 5);
  expectError(read(total), {f + ": byte ", "$Elements header announces 5 elements, the blocks hold 4"});
  // A block count too large: the text after the data is read as a block header.
  std::string blocks = good;
  put<std::uint64_t>(blocks, at.elementsHeader, 5);
  expectError(read(blocks), {f + ": byte " + std::to_string(good.size() - 14) + ":", "entity dimension"});
  // 8-byte sizes only.
  std::string size4 = good;
  size4.replace(size4.find("4.1 1 8"), 7, "4.1 1 4");
  expectError(read(size4), {f + ": byte 12:", "data-size 4"});
  // MSH 2.2 binary, truncated in the elements and with a block larger than the count.
  const std::string good22 = twoCubes22Binary().str();
  const std::size_t elements22 = good22.find("$Elements\n5\n") + 12;
  expectError(read(good22.substr(0, elements22 + 40)), {f + ": byte ", "file ends inside"});
  std::string block22 = good22;
  put<std::int32_t>(block22, elements22 + 4, 9);
  expectError(read(block22), {f + ": byte " + std::to_string(elements22 + 4) + ":",
                              "element block of 9 elements where 5 remain"});
  // A node that no $Nodes entry defines (binary element tags are located by byte).
  std::string unknown = good22;
  put<std::int32_t>(unknown, elements22 + 4 * 6, 99);
  expectError(read(unknown),
              {f + ": byte " + std::to_string(elements22 + 12) + ":", "element 1 refers to node 99"});
}

TEST(GmshFormats, RefusesNonHexahedraByName) {
  ScratchDir dir("gmsh_tets");
  const std::string f = dir.file("bad.msh");
  auto read = [&](const std::vector<std::string> &extra) {
    dir.write("bad.msh", twoCubes22(extra));
    return [f] { readGmsh(f); };
  };
  // Line 32 is the first extra element of twoCubes22().
  expectError(read({"300 4 2 1 3 11 12 13 15"}),
              {f + ":32:",
               "volume entity 3 (physical 'muscle tissue') contains tetrahedra (Gmsh type 4, "
               "4-node tetrahedron): Glossa needs hexahedra; mesh with Recombine/Transfinite",
               "'Mesh.SubdivisionAlgorithm = 2;'"});
  expectError(read({"300 11 2 0 3 11 12 13 15 16 17 18 19 20 21"}),
              {f + ":32:", "volume entity 3 contains tetrahedra (Gmsh type 11, 10-node tetrahedron)"});
  expectError(
      read({"300 6 2 1 3 11 12 13 15 16 17"}),
      {f + ":32:", "contains prisms (Gmsh type 6, 6-node prism)", "'Recombine Surface' before extruding"});
  expectError(read({"300 7 2 1 3 11 12 13 14 19"}),
              {f + ":32:", "contains pyramids (Gmsh type 7, 5-node pyramid)"});
  // Triangles in a face set are refused, but after the volumes, which may hold tetrahedra.
  expectError(
      read({"300 2 2 2 1 11 12 13"}),
      {f + ":32:", "surface entity 1 (physical 'floor') contains triangles (Gmsh type 2, 3-node triangle)"});
  expectError(read({"300 2 2 2 1 11 12 13", "301 4 2 1 3 11 12 13 15"}), {f + ":33:", "contains tetrahedra"});
  // Ungrouped triangles are not the mesh: skipped.
  EXPECT_EQ(readGmsh(dir.write("ok.msh", twoCubes22({"300 2 2 0 1 11 12 13"}))).mesh.numElements(), 2u);
  // Types Glossa does not know cannot be stepped over in MSH 2 (no entity dimension).
  expectError(read({"300 99 2 0 1 11"}),
              {f + ":32:", "element 300 has Gmsh type 99, which Glossa does not know"});
  // A copy with the same group is a true duplicate element: kept, and the mesh checks see it.
  const ImportedMesh dup = readGmsh(dir.write("dup.msh", twoCubes22({"202 5 2 1 2" + hexNodes(15)})));
  EXPECT_EQ(dup.mesh.numElements(), 3u);
  EXPECT_EQ(checkMesh(dup.mesh).duplicateElements.size(), 1u);
  // MSH 4.1 binary: a tetrahedron block in volume 2.
  Layout41 at;
  std::string tet = twoCubes41Binary(&at).str();
  const std::size_t block = tet.find(Bytes().i32(3).i32(2).i32(5).str(), at.elementsHeader);
  put<std::int32_t>(tet, block + 8, 4);
  dir.write("bad.msh", tet);
  expectError([f] { readGmsh(f); },
              {f + ": byte " + std::to_string(block) + ":",
               "volume entity 2 (physical 'muscle tissue', 'upper') contains tetrahedra (Gmsh type 4"});
}

// A bounded fuzz of both binary layouts: bytes flipped, 4- and 8-byte fields set to extreme
// values, the file cut anywhere. Every mutant is read or refused with a MeshError; anything
// else (another exception, a crash, an allocation the file cannot back) fails the test.
TEST(GmshFormats, BinaryMutantsAreReadOrRefused) {
  ScratchDir dir("gmsh_fuzz");
  const std::string f = dir.file("mutant.msh");
  std::mt19937_64 random(20261202);
  int refused = 0, read = 0;
  for (const std::string &good : {twoCubes22Binary().str(), twoCubes41Binary().str()}) {
    const std::size_t start = good.find("$EndMeshFormat");  // past the text a mutant would only break
    for (int i = 0; i < 600; ++i) {
      std::string bytes = good;
      const std::size_t at = start + random() % (bytes.size() - start - 8);
      switch (i % 4) {
        case 0:
          bytes[at] = static_cast<char>(bytes[at] ^ (1 << (random() % 8)));
          break;
        case 1:
          put<std::int32_t>(bytes, at, i % 8 < 4 ? -1 : std::numeric_limits<std::int32_t>::max());
          break;
        case 2:
          put<std::uint64_t>(bytes, at, std::uint64_t(1) << (32 + random() % 32));
          break;
        default:
          bytes.resize(at);
          break;
      }
      dir.write("mutant.msh", bytes);
      try {
        readGmsh(f);
        ++read;
      } catch (const MeshError &e) {
        EXPECT_EQ(std::string(e.what()).rfind(f + ":", 0), 0u) << e.what();
        ++refused;
      }
    }
  }
  // Most mutants break something; some (a flipped coordinate bit) are still a valid mesh.
  EXPECT_GT(refused, 600);
  EXPECT_GT(read, 10);
}

// One 20-node hexahedron (type 17, the unit cube, its 12 edge nodes 9..20 after the corners
// 1..8) with one edge node moved off the straight edge (a curved edge), its bottom as an 8-node
// quadrangle (type 16) in a physical surface, and node 99 that no element uses.
std::string serendipityCube(const std::string &version) {
  std::string s = "$MeshFormat\n" + version + " 0 8\n$EndMeshFormat\n";
  const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  // Gmsh's 20-node edge order: 0-1 0-3 0-4 1-2 1-5 2-3 2-6 3-7 4-5 4-7 5-6 6-7.
  const int edges[12][2] = {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
                            {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
  std::vector<std::array<double, 3>> x;
  for (const auto &c : corners) x.push_back({c[0], c[1], c[2]});
  for (const auto &e : edges) {
    std::array<double, 3> m;
    for (int k = 0; k < 3; ++k) m[static_cast<std::size_t>(k)] = 0.5 * (corners[e[0]][k] + corners[e[1]][k]);
    x.push_back(m);
  }
  x[8][1] = -0.2;  // edge 0-1 bulges outwards: the 20-node element is curved, the trilinear one is not
  std::string nodes, hex = "1 17", quad = "2 16";
  for (std::size_t n = 0; n < x.size(); ++n) {
    nodes += std::to_string(n + 1) + " " + std::to_string(x[n][0]) + " " + std::to_string(x[n][1]) + " " +
             std::to_string(x[n][2]) + "\n";
  }
  nodes += "99 5 5 5\n";
  if (version == "2.2") {
    s += "$Nodes\n21\n" + nodes + "$EndNodes\n$Elements\n2\n1 17 2 1 1";
    for (int a = 1; a <= 20; ++a) s += " " + std::to_string(a);
    // Bottom corners 1 4 3 2 (seen from outside), its edge nodes 0-3, 2-3, 1-2, 0-1.
    return s + "\n2 16 2 2 1 1 4 3 2 10 14 12 9\n$EndElements\n";
  }
  s += "$Entities\n0 0 1 1\n1 0 0 0 1 1 0 1 2 0\n1 0 0 0 1 1 1 1 1 0\n$EndEntities\n$Nodes\n1 21 1 99\n3 1 0 "
       "21\n";
  for (std::size_t n = 0; n < x.size(); ++n) s += std::to_string(n + 1) + "\n";
  s += "99\n";
  std::string coords;
  for (std::size_t n = 0; n < x.size(); ++n) {
    coords += std::to_string(x[n][0]) + " " + std::to_string(x[n][1]) + " " + std::to_string(x[n][2]) + "\n";
  }
  s += coords + "5 5 5\n$EndNodes\n$Elements\n2 2 1 2\n3 1 17 1\n1";
  for (int a = 1; a <= 20; ++a) s += " " + std::to_string(a);
  return s + "\n2 1 16 1\n2 1 4 3 2 10 14 12 9\n$EndElements\n";
}

TEST(GmshFormats, SecondOrderReadByCorners) {
  ScratchDir dir("gmsh_order2");
  for (const std::string &version : std::vector<std::string>{"2.2", "4.1"}) {
    SCOPED_TRACE("MSH " + version);
    const std::string f = dir.write("cube.msh", serendipityCube(version));
    const ImportedMesh imported = readGmsh(f);
    const HexMesh &mesh = imported.mesh;
    // The 12 edge nodes are dropped; the unused node 99 is the file's and stays (the mesh
    // checks before a run report it).
    ASSERT_EQ(mesh.numNodes(), 9u);
    EXPECT_EQ(imported.nodeFileIds, (std::vector<std::int64_t>{1, 2, 3, 4, 5, 6, 7, 8, 99}));
    EXPECT_FALSE(imported.hasNodeFileId(9));
    EXPECT_EQ(mesh.elements.at(0), (Hex{0, 1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(checkMesh(mesh).unusedNodes, std::vector<NodeId>{8});
    // Trilinear: the bulge of edge 0-1 is gone, the volume is the cube's.
    EXPECT_NEAR(meshVolume(mesh), 1.0, 1e-14);
    EXPECT_EQ(mesh.faceSets.at("physical2d_2"), (std::vector<ElementFace>{{0, 0}}));
    EXPECT_EQ(mesh.nodeSets.at("physical2d_2"), (std::vector<NodeId>{0, 1, 2, 3}));
    ASSERT_EQ(imported.notes.size(), 1u);
    const std::string &note = imported.notes[0];
    for (const std::string &fragment :
         std::vector<std::string>{f + ": second-order elements read by their corner nodes",
                                  "1 of Gmsh type 16 (8-node quadrangle)",
                                  "1 of Gmsh type 17 (20-node hexahedron)", "the geometry is made trilinear",
                                  "the 12 nodes only they used (edge, face and centre nodes) are dropped"}) {
      EXPECT_NE(note.find(fragment), std::string::npos) << fragment << " not in: " << note;
    }
  }
}

}  // namespace
}  // namespace glossa::mesh
