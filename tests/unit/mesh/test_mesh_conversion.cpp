// The tongue read from its ANSYS files, written as MSH 4.1 and Abaqus .inp, read back: the same
// mesh, sets and volume. Then the gmsh binary re-saves our .msh in both formats (its own parser
// and writers, so a misreading of either format on our side would not cancel out), and those
// files read back to the same counts, set sizes and volumes.

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>

#include "ImportTestSupport.hpp"
#include "mesh/AbaqusReader.hpp"
#include "mesh/AnsysReader.hpp"
#include "mesh/GmshReader.hpp"
#include "mesh/MeshQuality.hpp"

namespace glossa::mesh {
namespace {

using testing::ScratchDir;

const std::string kDir = std::string(GLOSSA_SOURCE_DIR) + "/inputs/tongue/";

// The tongue with its 21 muscle sets and the set of all elements, the jaw and hyoid node sets, and two face
// sets: the whole boundary and its part behind x = 0.12 (the base), so that face sets overlap.
ImportedMesh tongue() {
  AnsysModelFiles files;
  files.nodes = kDir + "tongue.node";
  files.elements = kDir + "tongue.elem";
  files.components = kDir + "CreateMuscles.mac";
  files.nodeSets = {{"jaw", kDir + "jaw_attachment_nodes.txt"},
                    {"hyoid", kDir + "hyoid_attachment_nodes.txt"}};
  ImportedMesh imported = readAnsysModel(files).imported;
  HexMesh &mesh = imported.mesh;
  // Gmsh saves only elements of physical groups: a group of all elements keeps the 176
  // elements that are in no muscle.
  mesh.elementSets["tongue"].resize(mesh.numElements());
  for (std::size_t e = 0; e < mesh.numElements(); ++e)
    mesh.elementSets["tongue"][e] = static_cast<ElementId>(e);
  mesh.faceSets["boundary"] = boundaryFaces(mesh);
  mesh.faceSets["base"] =
      facesInBox(mesh, mesh.faceSets["boundary"], Eigen::Vector3d(0.12, -1, -1), Eigen::Vector3d(1, 1, 1));
  return imported;
}

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// Sets an item belongs to, for grouping items into Gmsh entities: an entity carries a list of
// physical tags, so one entity per distinct combination represents overlapping sets exactly.
template <typename Item>
std::map<Item, std::vector<int>> memberships(const std::map<std::string, std::vector<Item>> &sets,
                                             int firstTag) {
  std::map<Item, std::vector<int>> result;
  int tag = firstTag;
  for (const auto &[name, items] : sets) {
    for (const Item &item : items) result[item].push_back(tag);
    ++tag;
  }
  return result;
}

// A minimal MSH 4.1 writer: all nodes in volume entity 1's node block; hexahedra grouped into
// volume entities by element-set combination; set faces as quadrangles grouped likewise into
// surface entities; node-set nodes as point elements of one point entity per node.
void writeMsh(const ImportedMesh &imported, const std::string &file) {
  const HexMesh &mesh = imported.mesh;
  std::ofstream out(file);
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n"
      << mesh.elementSets.size() + mesh.faceSets.size() + mesh.nodeSets.size() << "\n";
  int tag = 1;
  for (const auto &[name, s] : mesh.elementSets) out << "3 " << tag++ << " \"" << name << "\"\n";
  const int faceTag0 = tag;
  for (const auto &[name, s] : mesh.faceSets) out << "2 " << tag++ << " \"" << name << "\"\n";
  const int nodeTag0 = tag;
  for (const auto &[name, s] : mesh.nodeSets) out << "0 " << tag++ << " \"" << name << "\"\n";
  out << "$EndPhysicalNames\n";

  std::map<std::vector<int>, std::vector<ElementId>> volumes;
  auto elementTags = memberships(mesh.elementSets, 1);
  for (std::size_t e = 0; e < mesh.numElements(); ++e)
    volumes[elementTags[static_cast<ElementId>(e)]].push_back(e);
  std::map<std::vector<int>, std::vector<ElementFace>> surfaces;
  for (const auto &[face, tags] : memberships(mesh.faceSets, faceTag0)) surfaces[tags].push_back(face);
  const auto pointTags = memberships(mesh.nodeSets, nodeTag0);

  const auto [lo, hi] = boundingBox(mesh);
  std::string box;
  for (int i = 0; i < 3; ++i) box += number(lo[i]) + " ";
  for (int i = 0; i < 3; ++i) box += number(hi[i]) + " ";
  auto tagList = [](const std::vector<int> &tags) {
    std::string s = std::to_string(tags.size());
    for (int t : tags) s += " " + std::to_string(t);
    return s;
  };
  out << "$Entities\n" << pointTags.size() << " 0 " << surfaces.size() << " " << volumes.size() << "\n";
  for (const auto &[node, tags] : pointTags) {
    const auto &x = mesh.nodes[static_cast<std::size_t>(node)];
    out << node + 1 << " " << number(x.x()) << " " << number(x.y()) << " " << number(x.z()) << " "
        << tagList(tags) << "\n";
  }
  int entity = 1;
  for (const auto &[tags, faces] : surfaces) out << entity++ << " " << box << tagList(tags) << " 0\n";
  entity = 1;
  for (const auto &[tags, elements] : volumes) out << entity++ << " " << box << tagList(tags) << " 0\n";
  out << "$EndEntities\n";

  // A node of a point entity belongs to that entity's block (Gmsh classifies every node on
  // exactly one entity); the others to volume entity 1.
  auto writeNode = [&](std::size_t n) {
    const auto &x = mesh.nodes[n];
    return std::make_pair(std::to_string(imported.nodeFileIds[n]),
                          number(x.x()) + " " + number(x.y()) + " " + number(x.z()));
  };
  out << "$Nodes\n"
      << pointTags.size() + 1 << " " << mesh.numNodes() << " 1 "
      << *std::max_element(imported.nodeFileIds.begin(), imported.nodeFileIds.end()) << "\n";
  for (const auto &[node, tags] : pointTags) {
    const auto [id, x] = writeNode(static_cast<std::size_t>(node));
    out << "0 " << node + 1 << " 0 1\n" << id << "\n" << x << "\n";
  }
  std::vector<std::size_t> inVolume;
  for (std::size_t n = 0; n < mesh.numNodes(); ++n) {
    if (!pointTags.count(static_cast<NodeId>(n))) inVolume.push_back(n);
  }
  out << "3 1 0 " << inVolume.size() << "\n";
  for (std::size_t n : inVolume) out << writeNode(n).first << "\n";
  for (std::size_t n : inVolume) out << writeNode(n).second << "\n";
  out << "$EndNodes\n";

  std::size_t numFaces = 0;
  for (const auto &[tags, faces] : surfaces) numFaces += faces.size();
  const std::size_t total = mesh.numElements() + numFaces + pointTags.size();
  out << "$Elements\n"
      << volumes.size() + surfaces.size() + pointTags.size() << " " << total << " 1 " << total << "\n";
  // Hexahedra keep their ANSYS ids; faces and points get ids after them.
  std::int64_t next = *std::max_element(imported.elementFileIds.begin(), imported.elementFileIds.end()) + 1;
  entity = 1;
  for (const auto &[tags, elements] : volumes) {
    out << "3 " << entity++ << " 5 " << elements.size() << "\n";
    for (ElementId e : elements) {
      out << imported.elementFileIds[static_cast<std::size_t>(e)];
      for (NodeId n : mesh.elements[static_cast<std::size_t>(e)])
        out << " " << imported.nodeFileIds[static_cast<std::size_t>(n)];
      out << "\n";
    }
  }
  entity = 1;
  for (const auto &[tags, faces] : surfaces) {
    out << "2 " << entity++ << " 3 " << faces.size() << "\n";
    for (const ElementFace &f : faces) {
      out << next++;
      for (int a : kHexFaceNodes[static_cast<std::size_t>(f.localFace)]) {
        out << " "
            << imported.nodeFileIds[static_cast<std::size_t>(
                   mesh.elements[static_cast<std::size_t>(f.element)][a])];
      }
      out << "\n";
    }
  }
  for (const auto &[node, tags] : pointTags) {
    out << "0 " << node + 1 << " 15 1\n"
        << next++ << " " << imported.nodeFileIds[static_cast<std::size_t>(node)] << "\n";
  }
  out << "$EndElements\n";
}

// A minimal .inp writer: element lines split after the fourth node (a continuation line), sets
// sixteen ids per line, face sets as *SURFACE with Abaqus face numbers (local face + 1).
void writeInp(const ImportedMesh &imported, const std::string &file) {
  const HexMesh &mesh = imported.mesh;
  std::ofstream out(file);
  out << "*HEADING\ntongue converted by test_mesh_conversion\n*NODE\n";
  for (std::size_t n = 0; n < mesh.numNodes(); ++n) {
    const auto &x = mesh.nodes[n];
    out << imported.nodeFileIds[n] << ", " << number(x.x()) << ", " << number(x.y()) << ", " << number(x.z())
        << "\n";
  }
  out << "*ELEMENT, TYPE=C3D8H\n";
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    out << imported.elementFileIds[e];
    for (int a = 0; a < 8; ++a) {
      out << (a == 4 ? ",\n" : ", ") << imported.nodeFileIds[static_cast<std::size_t>(mesh.elements[e][a])];
    }
    out << "\n";
  }
  auto writeIds = [&out](const std::vector<std::int64_t> &ids) {
    for (std::size_t i = 0; i < ids.size(); ++i)
      out << ids[i] << (i % 16 == 15 || i + 1 == ids.size() ? ",\n" : ", ");
  };
  for (const auto &[name, s] : mesh.elementSets) {
    out << "*ELSET, ELSET=" << name << "\n";
    std::vector<std::int64_t> ids;
    for (ElementId e : s) ids.push_back(imported.elementFileIds[static_cast<std::size_t>(e)]);
    writeIds(ids);
  }
  for (const auto &[name, s] : mesh.nodeSets) {
    out << "*NSET, NSET=" << name << "\n";
    std::vector<std::int64_t> ids;
    for (NodeId n : s) ids.push_back(imported.nodeFileIds[static_cast<std::size_t>(n)]);
    writeIds(ids);
  }
  for (const auto &[name, s] : mesh.faceSets) {
    out << "*SURFACE, TYPE=ELEMENT, NAME=" << name << "\n";
    for (const ElementFace &f : s) {
      out << imported.elementFileIds[static_cast<std::size_t>(f.element)] << ", S" << f.localFace + 1 << "\n";
    }
  }
}

// The same mesh up to numbering (the MSH writer groups elements and nodes by entity): nodes
// bit for bit (%.17g round-trips) by file id, each element's nodes by file id and in the same
// local order, every set as the same file ids (faces as element id and local face).
void expectIdentical(const ImportedMesh &a, const ImportedMesh &b, const std::string &label) {
  ASSERT_EQ(a.mesh.numNodes(), b.mesh.numNodes()) << label;
  ASSERT_EQ(a.mesh.numElements(), b.mesh.numElements()) << label;
  for (std::size_t n = 0; n < a.mesh.numNodes(); ++n) {
    EXPECT_EQ(a.mesh.nodes[n], b.mesh.nodes[static_cast<std::size_t>(b.nodeOfFileId(a.nodeFileIds[n]))])
        << label;
  }
  auto nodeIds = [](const ImportedMesh &m, ElementId e) {
    std::vector<std::int64_t> ids;
    for (NodeId n : m.mesh.elements[static_cast<std::size_t>(e)])
      ids.push_back(m.nodeFileIds[static_cast<std::size_t>(n)]);
    return ids;
  };
  for (std::size_t e = 0; e < a.mesh.numElements(); ++e) {
    EXPECT_EQ(nodeIds(a, static_cast<ElementId>(e)), nodeIds(b, b.elementOfFileId(a.elementFileIds[e])))
        << label;
  }
  auto elementIds = [](const ImportedMesh &m, const std::vector<ElementId> &s) {
    std::set<std::int64_t> ids;
    for (ElementId e : s) ids.insert(m.elementFileIds[static_cast<std::size_t>(e)]);
    return ids;
  };
  auto nodeSetIds = [](const ImportedMesh &m, const std::vector<NodeId> &s) {
    std::set<std::int64_t> ids;
    for (NodeId n : s) ids.insert(m.nodeFileIds[static_cast<std::size_t>(n)]);
    return ids;
  };
  auto faceIds = [](const ImportedMesh &m, const std::vector<ElementFace> &s) {
    std::set<std::pair<std::int64_t, int>> ids;
    for (const ElementFace &f : s)
      ids.insert({m.elementFileIds[static_cast<std::size_t>(f.element)], f.localFace});
    return ids;
  };
  EXPECT_EQ(a.mesh.elementSets.size(), b.mesh.elementSets.size()) << label;
  for (const auto &[name, s] : a.mesh.elementSets) {
    EXPECT_EQ(elementIds(a, s), elementIds(b, b.mesh.elementSets.at(name))) << label << " " << name;
  }
  EXPECT_EQ(a.mesh.faceSets.size(), b.mesh.faceSets.size()) << label;
  for (const auto &[name, s] : a.mesh.faceSets) {
    EXPECT_EQ(faceIds(a, s), faceIds(b, b.mesh.faceSets.at(name))) << label << " " << name;
  }
  for (const auto &[name, s] : a.mesh.nodeSets) {
    EXPECT_EQ(nodeSetIds(a, s), nodeSetIds(b, b.mesh.nodeSets.at(name))) << label << " " << name;
  }
  const double V = meshVolume(a.mesh);
  EXPECT_NEAR(meshVolume(b.mesh), V, 1e-13 * V) << label;  // same elements, another summation order
}

// The volume of each element set: an invariant under any renumbering.
std::map<std::string, double> setVolumes(const HexMesh &mesh) {
  std::map<std::string, double> result;
  for (const auto &[name, s] : mesh.elementSets) {
    for (ElementId e : s) result[name] += elementVolume(mesh.elementCoordinates(e));
  }
  return result;
}

TEST(MeshConversion, TongueThroughMshAndInp) {
  const ImportedMesh original = tongue();
  ASSERT_EQ(original.mesh.elementSets.size(), 22u);
  ASSERT_GT(original.mesh.faceSets.at("base").size(), 0u);
  ScratchDir dir("conversion");
  writeMsh(original, dir.file("tongue.msh"));
  writeInp(original, dir.file("tongue.inp"));
  const ImportedMesh fromMsh = readGmsh(dir.file("tongue.msh"));
  const ImportedMesh fromInp = readAbaqus(dir.file("tongue.inp"));
  expectIdentical(original, fromMsh, "msh");
  expectIdentical(original, fromInp, "inp");
  // The face sets' node sets come along (Gmsh: always; Abaqus: no NSET of that name).
  EXPECT_EQ(fromMsh.mesh.nodeSets.at("base"), fromMsh.mesh.nodesOfFaceSet("base"));
  EXPECT_EQ(fromInp.mesh.nodeSets.at("base"), fromInp.mesh.nodesOfFaceSet("base"));
  EXPECT_EQ(fromMsh.mesh.nodeSets.at("base").size(), original.mesh.nodesOfFaceSet("base").size());
  EXPECT_NEAR(meshVolume(fromMsh.mesh), 1.0229167206054071e-4, 1e-12);
}

TEST(MeshConversion, TongueResavedByGmsh) {
  const std::string gmsh = GLOSSA_GMSH_EXECUTABLE;
  if (gmsh.empty()) GTEST_SKIP() << "gmsh binary not found at configure time";
  const ImportedMesh original = tongue();
  ScratchDir dir("conversion_gmsh");
  writeMsh(original, dir.file("ours.msh"));
  const std::string msh = dir.file("gmsh.msh"), inp = dir.file("gmsh.inp");
  ASSERT_EQ(
      std::system((gmsh + " " + dir.file("ours.msh") + " -save -format msh41 -o " + msh + " > /dev/null 2>&1")
                      .c_str()),
      0);
  ASSERT_EQ(
      std::system((gmsh + " " + dir.file("ours.msh") +
                   " -setnumber Mesh.SaveGroupsOfNodes 1 -save -format inp -o " + inp + " > /dev/null 2>&1")
                      .c_str()),
      0);
  const double V = meshVolume(original.mesh);
  const auto volumes = setVolumes(original.mesh);
  for (const std::string &file : {msh, inp}) {
    const ImportedMesh back = file == msh ? readGmsh(file) : readAbaqus(file);
    EXPECT_EQ(back.mesh.numNodes(), 946u) << file;
    EXPECT_EQ(back.mesh.numElements(), 740u) << file;
    EXPECT_NEAR(meshVolume(back.mesh), V, 1e-15 * V * 740) << file;
    for (const auto &[name, s] : original.mesh.elementSets) {
      ASSERT_TRUE(back.mesh.elementSets.count(name)) << file << " " << name;
      EXPECT_EQ(back.mesh.elementSets.at(name).size(), s.size()) << file << " " << name;
      EXPECT_NEAR(setVolumes(back.mesh).at(name), volumes.at(name), 1e-12 * V) << file << " " << name;
    }
    for (const auto &[name, s] : original.mesh.faceSets) {
      ASSERT_TRUE(back.mesh.faceSets.count(name)) << file << " " << name;
      EXPECT_EQ(back.mesh.faceSets.at(name).size(), s.size()) << file << " " << name;
    }
    for (const std::string name : {"jaw", "hyoid"}) {
      ASSERT_TRUE(back.mesh.nodeSets.count(name)) << file << " " << name;
      std::set<std::vector<double>> a, b;
      for (NodeId n : original.mesh.nodeSets.at(name)) {
        const auto &x = original.mesh.nodes[static_cast<std::size_t>(n)];
        a.insert({x.x(), x.y(), x.z()});
      }
      for (NodeId n : back.mesh.nodeSets.at(name)) {
        const auto &x = back.mesh.nodes[static_cast<std::size_t>(n)];
        b.insert({x.x(), x.y(), x.z()});
      }
      EXPECT_EQ(a, b) << file << " " << name;  // same points, whatever the numbering
    }
  }
}

}  // namespace
}  // namespace glossa::mesh
