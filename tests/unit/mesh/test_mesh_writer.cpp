// The MSH 4.1 and Abaqus writers behind `glossa mesh --output OUT.msh|OUT.inp`, read back by
// Glossa's readers: the same nodes (bit for bit), the same elements in the same order and every
// set, face sets included. With the gmsh binary, Gmsh re-saves the written .msh (its parser and
// writers, MSH 4.1 and 2.2) and that reads back to the same mesh too, up to numbering.

#include <gtest/gtest.h>

#include <cstdlib>
#include <map>

#include "ImportTestSupport.hpp"
#include "mesh/AbaqusReader.hpp"
#include "mesh/BoxGenerator.hpp"
#include "mesh/GmshReader.hpp"
#include "mesh/MeshError.hpp"
#include "mesh/MeshWriter.hpp"

namespace glossa::mesh {
namespace {

using testing::expectError;
using testing::ScratchDir;

// A 3 x 2 x 2 box with the generator's six sides, plus overlapping element sets, a face set that
// overlaps the sides, one on an interior surface (x = 1, as faces of the elements at x < 1:
// their outward normal is +x) and node sets of their own.
HexMesh sampleMesh() {
  HexMesh mesh = generateBox(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3, 2, 2), {3, 2, 2});
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    const Eigen::Vector3d c = mesh.elementCoordinates(static_cast<ElementId>(e)).colwise().mean();
    if (c.x() < 1) mesh.elementSets["left third"].push_back(static_cast<ElementId>(e));
    if (c.z() > 1) mesh.elementSets["upper"].push_back(static_cast<ElementId>(e));
    if (c.x() < 1) mesh.faceSets["cut"].push_back({static_cast<ElementId>(e), 3});  // local face 3: xi = +1
  }
  mesh.faceSets["zmin and some"] = mesh.faceSets.at("zmin");
  mesh.faceSets["zmin and some"].push_back(mesh.faceSets.at("xmax").front());
  std::sort(mesh.faceSets["zmin and some"].begin(), mesh.faceSets["zmin and some"].end());
  // Readers give every face set the node set of its nodes; here they are the mesh's own.
  mesh.nodeSets["cut"] = mesh.nodesOfFaceSet("cut");
  mesh.nodeSets["zmin and some"] = mesh.nodesOfFaceSet("zmin and some");
  mesh.nodeSets["pinned"] = {0, 5, 7};
  mesh.nodeSets["single"] = {5};
  return mesh;
}

void expectSameMesh(const HexMesh &read, const HexMesh &written) {
  EXPECT_EQ(read.nodes, written.nodes);
  EXPECT_EQ(read.elements, written.elements);
  EXPECT_EQ(read.elementSets, written.elementSets);
  EXPECT_EQ(read.faceSets, written.faceSets);
  EXPECT_EQ(read.nodeSets, written.nodeSets);
}

TEST(MeshWriter, GmshRoundTrip) {
  ScratchDir dir("writer_msh");
  const HexMesh mesh = sampleMesh();
  const std::string file = dir.file("box.msh");
  writeGmsh(mesh, file);
  const ImportedMesh imported = readGmsh(file);
  expectSameMesh(imported.mesh, mesh);
  EXPECT_EQ(imported.nodeFileIds.front(), 1);
  EXPECT_EQ(imported.elementFileIds.back(), static_cast<std::int64_t>(mesh.numElements()));
}

TEST(MeshWriter, AbaqusRoundTrip) {
  ScratchDir dir("writer_inp");
  const HexMesh mesh = sampleMesh();
  const std::string file = dir.file("box.inp");
  writeAbaqus(mesh, file);
  expectSameMesh(readAbaqus(file).mesh, mesh);
}

TEST(MeshWriter, GmshResavesWhatIsWritten) {
  const std::string gmsh = GLOSSA_GMSH_EXECUTABLE;
  if (gmsh.empty()) GTEST_SKIP() << "gmsh binary not found at configure time";
  ScratchDir dir("writer_gmsh");
  const HexMesh mesh = sampleMesh();
  const std::string file = dir.file("box.msh");
  writeGmsh(mesh, file);
  for (const std::string &format : std::vector<std::string>{"msh41", "msh22"}) {
    SCOPED_TRACE(format);
    const std::string again = dir.file("again_" + format + ".msh");
    const std::string command =
        gmsh + " " + file + " -0 -format " + format + " -o " + again + " > /dev/null 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const HexMesh read = readGmsh(again).mesh;
    // Gmsh's MSH 2 writer renumbers nodes: match nodes by position, elements by their nodes.
    ASSERT_EQ(read.numNodes(), mesh.numNodes());
    ASSERT_EQ(read.numElements(), mesh.numElements());
    std::map<std::array<double, 3>, NodeId> nodeAt;
    for (std::size_t n = 0; n < read.numNodes(); ++n) {
      nodeAt[{read.nodes[n].x(), read.nodes[n].y(), read.nodes[n].z()}] = static_cast<NodeId>(n);
    }
    std::map<Hex, ElementId> elementOf;
    for (std::size_t e = 0; e < read.numElements(); ++e)
      elementOf[read.elements[e]] = static_cast<ElementId>(e);
    std::vector<NodeId> node(mesh.numNodes());  // written node -> node read
    for (std::size_t n = 0; n < mesh.numNodes(); ++n) {
      const auto it = nodeAt.find({mesh.nodes[n].x(), mesh.nodes[n].y(), mesh.nodes[n].z()});
      ASSERT_NE(it, nodeAt.end()) << "node " << n;
      node[n] = it->second;
    }
    std::vector<ElementId> element(mesh.numElements());
    for (std::size_t e = 0; e < mesh.numElements(); ++e) {
      Hex expected;
      for (int a = 0; a < 8; ++a) expected[a] = node[static_cast<std::size_t>(mesh.elements[e][a])];
      const auto it = elementOf.find(expected);
      ASSERT_NE(it, elementOf.end()) << "element " << e << " (its node order included)";
      element[e] = it->second;
    }
    for (const auto &[name, set] : mesh.elementSets) {
      std::vector<ElementId> expected;
      for (ElementId e : set) expected.push_back(element[static_cast<std::size_t>(e)]);
      std::sort(expected.begin(), expected.end());
      EXPECT_EQ(read.elementSets.at(name), expected) << name;
    }
    for (const auto &[name, set] : mesh.faceSets) {
      std::vector<ElementFace> expected;
      for (ElementFace f : set)
        expected.push_back({element[static_cast<std::size_t>(f.element)], f.localFace});
      std::sort(expected.begin(), expected.end());
      EXPECT_EQ(read.faceSets.at(name), expected) << name;
    }
    for (const auto &[name, set] : mesh.nodeSets) {
      std::vector<NodeId> expected;
      for (NodeId n : set) expected.push_back(node[static_cast<std::size_t>(n)]);
      std::sort(expected.begin(), expected.end());
      EXPECT_EQ(read.nodeSets.at(name), expected) << name;
    }
  }
}

TEST(MeshWriter, RefusesWhatTheFormatCannotHold) {
  ScratchDir dir("writer_bad");
  HexMesh mesh = sampleMesh();
  mesh.nodeSets["zmin"].pop_back();  // no longer the nodes of face set zmin
  const std::string msh = dir.file("bad.msh");
  expectError([&] { writeGmsh(mesh, msh); },
              {msh + ": node set 'zmin' has the name of a face set but other nodes"});
  EXPECT_NO_THROW(writeAbaqus(mesh, dir.file("ok.inp")));  // an NSET says it exactly
  EXPECT_EQ(readAbaqus(dir.file("ok.inp")).mesh.nodeSets.at("zmin"), mesh.nodeSets.at("zmin"));
  HexMesh comma = sampleMesh();
  comma.elementSets["a,b"] = {0};
  const std::string inp = dir.file("bad.inp");
  expectError([&] { writeAbaqus(comma, inp); },
              {inp + ": set name 'a,b' cannot stand in an Abaqus keyword line"});
  expectError([&] { writeGmsh(sampleMesh(), dir.file("no/such/dir.msh")); },
              {"no/such/dir.msh: cannot write"});
}

}  // namespace
}  // namespace glossa::mesh
