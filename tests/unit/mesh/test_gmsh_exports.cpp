// One .geo meshed by the real gmsh binary and exported five ways (MSH 2.2 ASCII and binary,
// MSH 4.1 ASCII and binary, Abaqus .inp): the five imports must be the same mesh, the same
// elements and the same sets, compared by position (each format is free to number nodes and
// elements its own way). Second-order exports must read as the first-order mesh (their corners),
// and a tetrahedral mesh is refused by name, while Gmsh's own remedy for it, subdivision into
// hexahedra, gives a mesh the reader takes. Skipped when gmsh was not found at configure time.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <set>

#include "ImportTestSupport.hpp"
#include "MeshTestChecks.hpp"
#include "mesh/AbaqusReader.hpp"
#include "mesh/GmshReader.hpp"
#include "mesh/MeshChecks.hpp"
#include "mesh/MeshQuality.hpp"

namespace glossa::mesh {
namespace {

using testing::expectError;
using testing::ScratchDir;

// A 2 x 1 x 3 box: a transfinite recombined 4 x 2 base extruded in 3 layers (24 hexahedra,
// 5 x 3 x 4 = 60 nodes), with physical groups for the volume, the base, the top, the side
// y = 0, an edge and a corner point; the volume is in two groups, which MSH 2 writes as two
// copies of each hexahedron.
const char *kGeo = R"(SetFactory("Built-in");
Point(1) = {0,0,0}; Point(2) = {2,0,0}; Point(3) = {2,1,0}; Point(4) = {0,1,0};
Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};
Curve Loop(1) = {1,2,3,4}; Plane Surface(1) = {1};
Transfinite Curve{1,3} = 5; Transfinite Curve{2,4} = 3; Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {0,0,3} { Surface{1}; Layers{3}; Recombine; };
Physical Volume("tissue") = {out[1]};
Physical Volume("whole") = {out[1]};
Physical Surface("base") = {1};
Physical Surface("top") = {out[0]};
Physical Surface("side") = {out[2]};
Physical Curve("edge") = {1};
Physical Point("origin") = {1};
)";

// A mesh in terms of positions only: nodes as points, elements as their 8 corner points in
// order, sets as sets of those.
using Point = std::array<double, 3>;
struct ByPosition {
  std::set<Point> nodes;
  std::set<std::array<Point, 8>> elements;
  std::map<std::string, std::set<std::array<Point, 8>>> elementSets;
  std::map<std::string, std::set<std::array<Point, 4>>> faceSets;  // each face's points sorted
  std::map<std::string, std::set<Point>> nodeSets;
};

// Exports print coordinates with different digits (the .inp has 14 significant ones):
// positions are compared on a 1e-9 grid, far below the 0.5 spacing.
Point at(const HexMesh &mesh, NodeId n) {
  const Eigen::Vector3d &x = mesh.nodes[static_cast<std::size_t>(n)];
  return {std::round(x[0] * 1e9) / 1e9, std::round(x[1] * 1e9) / 1e9, std::round(x[2] * 1e9) / 1e9};
}

ByPosition byPosition(const HexMesh &mesh, const std::set<std::string> &names) {
  ByPosition p;
  auto hex = [&](ElementId e) {
    std::array<Point, 8> h;
    for (int a = 0; a < 8; ++a)
      h[static_cast<std::size_t>(a)] = at(mesh, mesh.elements[static_cast<std::size_t>(e)][a]);
    return h;
  };
  for (std::size_t n = 0; n < mesh.numNodes(); ++n) p.nodes.insert(at(mesh, static_cast<NodeId>(n)));
  for (std::size_t e = 0; e < mesh.numElements(); ++e) p.elements.insert(hex(static_cast<ElementId>(e)));
  for (const auto &[name, set] : mesh.elementSets) {
    if (!names.count(name)) continue;
    for (ElementId e : set) p.elementSets[name].insert(hex(e));
  }
  for (const auto &[name, set] : mesh.faceSets) {
    if (!names.count(name)) continue;
    for (const ElementFace &f : set) {
      std::array<Point, 4> q;
      for (int a = 0; a < 4; ++a) {
        q[static_cast<std::size_t>(a)] =
            at(mesh, mesh.elements[static_cast<std::size_t>(f.element)][kHexFaceNodes[f.localFace][a]]);
      }
      std::sort(q.begin(), q.end());
      p.faceSets[name].insert(q);
    }
  }
  for (const auto &[name, set] : mesh.nodeSets) {
    if (!names.count(name)) continue;
    for (NodeId n : set) p.nodeSets[name].insert(at(mesh, n));
  }
  return p;
}

class GmshExports : public ::testing::Test {
 protected:
  void SetUp() override {
    if (gmsh_.empty()) GTEST_SKIP() << "gmsh binary not found at configure time";
  }
  // Runs gmsh on the box with `options`, writing `name`; returns its path.
  std::string mesh(const std::string &name, const std::string &options, const std::string &geo = kGeo) {
    const std::string geoFile = dir_.write(name + ".geo", geo), out = dir_.file(name);
    const std::string command =
        gmsh_ + " -3 " + geoFile + " " + options + " -o " + out + " > " + out + ".log 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return out;
  }
  const std::string gmsh_ = GLOSSA_GMSH_EXECUTABLE;
  ScratchDir dir_{"gmsh_exports"};
};

const std::set<std::string> kGroups = {"tissue", "whole", "base", "top", "side", "edge", "origin"};

void expectSame(const ByPosition &a, const ByPosition &b) {
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.elements, b.elements);
  EXPECT_EQ(a.elementSets, b.elementSets);
  EXPECT_EQ(a.faceSets, b.faceSets);
  EXPECT_EQ(a.nodeSets, b.nodeSets);
}

TEST_F(GmshExports, FiveFormatsGiveTheSameMesh) {
  const ImportedMesh reference = readGmsh(mesh("box41.msh", "-format msh41"));
  const HexMesh &m = reference.mesh;
  // The reference itself, against the geometry.
  ASSERT_EQ(m.numElements(), 24u);
  ASSERT_EQ(m.numNodes(), 60u);
  EXPECT_NEAR(meshVolume(m), 6.0, 1e-12);
  EXPECT_NEAR(testing::volumeByDivergence(m), 6.0, 1e-12);
  EXPECT_EQ(m.elementSets.at("tissue").size(), 24u);
  EXPECT_EQ(m.faceSets.at("base").size(), 8u);
  EXPECT_EQ(m.faceSets.at("top").size(), 8u);
  EXPECT_EQ(m.faceSets.at("side").size(), 12u);
  for (const ElementFace &f : m.faceSets.at("side")) EXPECT_NEAR(faceCentroid(m, f).y(), 0.0, 1e-12);
  testing::expectOutwardNormals(m, "side");
  EXPECT_EQ(m.nodeSets.at("side").size(), 20u);
  EXPECT_EQ(m.nodeSets.at("edge").size(), 5u);
  EXPECT_EQ(m.nodeSets.at("origin").size(), 1u);
  EXPECT_TRUE(checkMesh(m).unusedNodes.empty());
  const ByPosition expected = byPosition(m, kGroups);
  EXPECT_EQ(m.elementSets.at("whole"), m.elementSets.at("tissue"));
  ASSERT_EQ(expected.elementSets.size() + expected.faceSets.size(), 5u);
  ASSERT_EQ(expected.nodeSets.size(), 5u);  // the three surfaces' node sets, the edge, the point

  for (const auto &[name, options] :
       std::vector<std::pair<std::string, std::string>>{{"box22.msh", "-format msh22"},
                                                        {"box22b.msh", "-format msh22 -bin"},
                                                        {"box41b.msh", "-format msh41 -bin"}}) {
    SCOPED_TRACE(name);
    const ImportedMesh imported = readGmsh(mesh(name, options));
    EXPECT_EQ(imported.mesh.numNodes(), 60u);
    EXPECT_EQ(imported.mesh.numElements(), 24u);
    EXPECT_TRUE(imported.notes.empty());
    expectSame(byPosition(imported.mesh, kGroups), expected);
  }
  // The .inp: Gmsh writes the volume, surface and curve groups as ELSETs (of hexahedra, of
  // quadrilaterals: face sets with their node sets, of T3D2 lines: node sets) and no physical
  // points.
  const ImportedMesh inp = readAbaqus(mesh("box.inp", "-format inp"));
  EXPECT_EQ(inp.mesh.numNodes(), 60u);
  EXPECT_EQ(inp.mesh.numElements(), 24u);
  ByPosition fromMsh = expected;
  fromMsh.nodeSets.erase("origin");
  expectSame(byPosition(inp.mesh, kGroups), fromMsh);
}

// -save_all: MSH 4.1 keeps the groups; Gmsh's MSH 2 writer drops them (physical tag 0), which
// the reader notes instead of returning a mesh whose missing sets a deck would only meet later.
TEST_F(GmshExports, SaveAll) {
  const ImportedMesh all41 = readGmsh(mesh("all41.msh", "-save_all -format msh41 -bin"));
  EXPECT_EQ(all41.mesh.numElements(), 24u);
  EXPECT_EQ(all41.mesh.faceSets.at("side").size(), 12u);
  EXPECT_TRUE(all41.notes.empty());
  const ImportedMesh all22 = readGmsh(mesh("all22.msh", "-save_all -format msh22"));
  EXPECT_EQ(all22.mesh.numElements(), 24u);
  EXPECT_TRUE(all22.mesh.elementSets.empty());
  ASSERT_EQ(all22.notes.size(), 1u);
  EXPECT_NE(all22.notes[0].find("no element carries a physical tag"), std::string::npos);
}

TEST_F(GmshExports, SecondOrderReadAsItsCorners) {
  const ByPosition expected = byPosition(readGmsh(mesh("box.msh", "-format msh41")).mesh, kGroups);
  for (const auto &[name, options, types] : std::vector<std::array<std::string, 3>>{
           {"o2.msh", "-order 2 -format msh41", "Gmsh type 12 (27-node hexahedron)"},
           {"o2b.msh", "-order 2 -format msh22 -bin", "Gmsh type 10 (9-node quadrangle)"},
           {"o2s.msh", "-order 2 -string 'Mesh.SecondOrderIncomplete = 1;' -format msh41 -bin",
            "Gmsh type 17 (20-node hexahedron)"}}) {
    SCOPED_TRACE(name);
    const ImportedMesh imported = readGmsh(mesh(name, options));
    EXPECT_EQ(imported.mesh.numNodes(), 60u);
    expectSame(byPosition(imported.mesh, kGroups), expected);
    EXPECT_TRUE(checkMesh(imported.mesh).unusedNodes.empty());
    ASSERT_EQ(imported.notes.size(), 1u);
    EXPECT_NE(imported.notes[0].find(types), std::string::npos) << imported.notes[0];
    EXPECT_NE(imported.notes[0].find("the geometry is made trilinear"), std::string::npos);
  }
}

TEST_F(GmshExports, TetrahedraRefusedSubdivisionRead) {
  // The same box meshed freely: tetrahedra (and triangles on its physical surfaces).
  std::string geo = kGeo;
  geo.replace(geo.find("Transfinite Curve"), geo.find("out[]") - geo.find("Transfinite Curve"), "");
  geo.replace(geo.find(" Layers{3}; Recombine;"), 22, "");
  const std::string tets = mesh("tets.msh", "-format msh41", geo);
  expectError([&] { readGmsh(tets); },
              {tets + ":", "contains tetrahedra (Gmsh type 4, 4-node tetrahedron): Glossa needs hexahedra"});
  const std::string tets22 = mesh("tets22.msh", "-format msh22 -bin", geo);
  expectError([&] { readGmsh(tets22); }, {tets22 + ": byte ", "contains tetrahedra (Gmsh type 4"});
  // The advice works: Mesh.SubdivisionAlgorithm = 2 splits every element into hexahedra.
  const ImportedMesh split =
      readGmsh(mesh("split.msh", "-string 'Mesh.SubdivisionAlgorithm = 2;' -format msh41", geo));
  EXPECT_GT(split.mesh.numElements(), 24u);
  EXPECT_NEAR(meshVolume(split.mesh), 6.0, 1e-9);
  EXPECT_EQ(split.mesh.elementSets.at("tissue").size(), split.mesh.numElements());
  EXPECT_FALSE(split.mesh.faceSets.at("side").empty());
  for (const ElementFace &f : split.mesh.faceSets.at("side"))
    EXPECT_NEAR(faceCentroid(split.mesh, f).y(), 0.0, 1e-9);
}

}  // namespace
}  // namespace glossa::mesh
