// The ANSYS reader on the real ICP/GIPSA tongue (counts from its README and hand-read macro
// lines) and on small malformed files written here.

#include <gtest/gtest.h>

#include <set>

#include "ImportTestSupport.hpp"
#include "mesh/AnsysReader.hpp"
#include "mesh/MeshQuality.hpp"

namespace glossa::mesh {
namespace {

using testing::expectError;
using testing::ScratchDir;

const std::string kDir = std::string(GLOSSA_SOURCE_DIR) + "/inputs/tongue/";

// The styloid anchors of the README, on the side of their bundle: STY_L fibres lie at y < 0.
std::map<std::int64_t, Eigen::Vector3d> styloidAnchors() {
  return {{4037, Eigen::Vector3d(0.14984029, -0.035891287, 0.125)},
          {4042, Eigen::Vector3d(0.14984029, +0.035891287, 0.125)}};
}

AnsysModel readTongue() {
  AnsysModelFiles files;
  files.nodes = kDir + "tongue.node";
  files.elements = kDir + "tongue.elem";
  files.components = kDir + "CreateMuscles.mac";
  files.fibres = kDir + "Fibers.mac";
  files.nodeSets = {{"jaw", kDir + "jaw_attachment_nodes.txt"},
                    {"hyoid", kDir + "hyoid_attachment_nodes.txt"}};
  files.externalPoints = styloidAnchors();
  return readAnsysModel(files);
}

TEST(AnsysReader, TongueCountsAndIds) {
  const AnsysModel model = readTongue();
  const HexMesh &mesh = model.imported.mesh;
  EXPECT_EQ(mesh.numNodes(), 946u);
  EXPECT_EQ(mesh.numElements(), 740u);
  for (std::size_t n = 0; n < mesh.numNodes(); ++n)
    EXPECT_EQ(model.imported.nodeFileIds[n], std::int64_t(n + 1));
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    EXPECT_EQ(model.imported.elementFileIds[e], std::int64_t(e + 1));
  }
  // First line of tongue.elem: "11 9 8 10 170 171 168 169 ... 1", copied in order, 0-based.
  EXPECT_EQ(mesh.elements[0], (Hex{10, 8, 7, 9, 169, 170, 167, 168}));
  // Last line: "507 701 702 508 554 707 711 579 ... 740".
  EXPECT_EQ(mesh.elements[739], (Hex{506, 700, 701, 507, 553, 706, 710, 578}));
  // README: tip node 920 at (0.0576, 0, 0.0999); the bounding box.
  EXPECT_NEAR((mesh.nodes[model.imported.nodeOfFileId(920)] - Eigen::Vector3d(0.0576, 0, 0.0999)).norm(), 0,
              1e-4);
  const auto [lo, hi] = boundingBox(mesh);
  EXPECT_NEAR(lo.x(), 0.0569, 1e-4);
  EXPECT_NEAR(hi.x(), 0.1310, 1e-4);
  EXPECT_NEAR(lo.z(), 0.0546, 1e-4);
  EXPECT_NEAR(hi.z(), 0.1140, 1e-4);
  EXPECT_NEAR(hi.y(), 0.0325, 1e-4);
  EXPECT_NEAR(lo.y(), -0.0325, 1e-4);
}

TEST(AnsysReader, TongueElementsArePositiveAndVolumeAgreesTwoWays) {
  const HexMesh &mesh = readTongue().imported.mesh;
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    EXPECT_GT(minGaussPointJacobian(mesh.elementCoordinates(static_cast<ElementId>(e))), 0.0) << e;
  }
  // Sum of element volumes (2x2x2 Gauss, exact for trilinear hexes) against the divergence
  // theorem over the 2x2-Gauss bilinear boundary faces: equal up to round-off only if the
  // boundary is closed and every element is consistently oriented.
  const double V = meshVolume(mesh);
  EXPECT_NEAR(V, testing::volumeByDivergence(mesh), 1e-12 * V);
  // And against numpy on the raw files (independent script, same formula): 1.0229167206054071e-4.
  EXPECT_NEAR(V, 1.0229167206054071e-4, 1e-12);
}

TEST(AnsysReader, TongueMuscleSets) {
  const AnsysModel model = readTongue();
  const HexMesh &mesh = model.imported.mesh;
  const std::vector<std::string> expected = {
      "GGP_L", "GGP_R", "GGM_L", "GGM_R",  "GGA_L",  "GGA_R",   "STY_L",   "STY_R", "GH_L", "GH_R", "MH_L",
      "MH_R",  "HG_L",  "HG_R",  "VERT_L", "VERT_R", "TRANS_L", "TRANS_R", "IL_L",  "IL_R", "SL"};
  EXPECT_EQ(model.components.names, expected);
  EXPECT_EQ(model.components.declaredNames, expected);
  EXPECT_EQ(mesh.elementSets.size(), 21u);
  // CM,NEW_TISSUE,ELEM after ESEL,NONE: an empty component, reported but not a set.
  EXPECT_EQ(model.components.emptyComponents, std::vector<std::string>{"NEW_TISSUE"});
  EXPECT_EQ(model.components.groups.size(), 10u);
  EXPECT_EQ(model.components.groups.at("TRANS"), (std::vector<std::string>{"TRANS_L", "TRANS_R"}));

  std::set<ElementId> any;
  for (const auto &[name, set] : mesh.elementSets) any.insert(set.begin(), set.end());
  EXPECT_EQ(any.size(), 564u);  // README

  // GGM_L by hand from the macro: 126, 128, 150, 157, 180, 243..249 step 2, 344, 347 (1-based).
  EXPECT_EQ(mesh.elementSets.at("GGM_L"),
            (std::vector<ElementId>{125, 127, 149, 156, 179, 242, 244, 246, 248, 343, 346}));
  // README: VERT_L lies inside TRANS_L; TRANS shares elements with GGP and SL.
  const auto &vert = mesh.elementSets.at("VERT_L"), &trans = mesh.elementSets.at("TRANS_L");
  EXPECT_TRUE(std::includes(trans.begin(), trans.end(), vert.begin(), vert.end()));
  auto shares = [&](const std::string &a, const std::string &b) {
    std::vector<ElementId> common;
    std::set_intersection(mesh.elementSets.at(a).begin(), mesh.elementSets.at(a).end(),
                          mesh.elementSets.at(b).begin(), mesh.elementSets.at(b).end(),
                          std::back_inserter(common));
    return !common.empty();
  };
  EXPECT_TRUE(shares("TRANS_L", "GGP_L") || shares("TRANS_R", "GGP_R"));
  EXPECT_TRUE(shares("TRANS_L", "SL") || shares("TRANS_R", "SL"));
}

TEST(AnsysReader, TongueFibres) {
  const AnsysModel model = readTongue();
  ASSERT_EQ(model.fibres.size(), 21u);
  std::size_t fibres = 0, segments = 0;
  for (const MuscleFibres &m : model.fibres) {
    fibres += m.fibres.size();
    for (const auto &f : m.fibres) segments += f.size() - 1;
  }
  EXPECT_EQ(fibres, 308u);     // README
  EXPECT_EQ(segments, 1574u);  // README
  // Fibers.mac lines 48..59: fibre 1 of GGP_L is 398 397 134 271 124 116 111 110 204 205 206 121.
  const std::vector<std::int64_t> first = {398, 397, 134, 271, 124, 116, 111, 110, 204, 205, 206, 121};
  ASSERT_EQ(model.fibres[0].muscle, "GGP_L");
  ASSERT_EQ(model.fibres[0].fibres[0].size(), first.size());
  for (std::size_t k = 0; k < first.size(); ++k) {
    const FibrePoint &p = model.fibres[0].fibres[0][k];
    EXPECT_EQ(p.fileId, first[k]);
    EXPECT_EQ(p.node, first[k] - 1);
    EXPECT_EQ(p.position, model.imported.mesh.nodes[static_cast<std::size_t>(first[k] - 1)]);
  }
  // Every STY fibre ends at its side's styloid anchor, an external point; no other fibre
  // touches an external point.
  for (const MuscleFibres &m : model.fibres) {
    for (const auto &f : m.fibres) {
      for (std::size_t k = 0; k < f.size(); ++k) {
        const bool last = k + 1 == f.size();
        if (m.muscle == "STY_L" && last) {
          EXPECT_EQ(f[k].fileId, 4037);
          EXPECT_EQ(f[k].node, -1);
          EXPECT_EQ(f[k].position, styloidAnchors().at(4037));
        } else if (m.muscle == "STY_R" && last) {
          EXPECT_EQ(f[k].fileId, 4042);
          EXPECT_EQ(f[k].position, styloidAnchors().at(4042));
        } else {
          EXPECT_GE(f[k].node, 0) << m.muscle;
        }
      }
    }
  }
}

TEST(AnsysReader, TongueAttachmentNodeSets) {
  const HexMesh &mesh = readTongue().imported.mesh;
  ASSERT_EQ(mesh.nodeSets.at("jaw").size(), 59u);    // README
  ASSERT_EQ(mesh.nodeSets.at("hyoid").size(), 56u);  // README
  // README boxes: jaw x 0.0757-0.1056, z 0.0572-0.0842; hyoid x 0.1074-0.1310, z 0.0546-0.0654.
  for (NodeId n : mesh.nodeSets.at("jaw")) {
    const auto &x = mesh.nodes[static_cast<std::size_t>(n)];
    EXPECT_TRUE(x.x() > 0.0757 - 1e-4 && x.x() < 0.1056 + 1e-4 && x.z() > 0.0572 - 1e-4 &&
                x.z() < 0.0842 + 1e-4);
  }
  for (NodeId n : mesh.nodeSets.at("hyoid")) {
    const auto &x = mesh.nodes[static_cast<std::size_t>(n)];
    EXPECT_TRUE(x.x() > 0.1074 - 1e-4 && x.x() < 0.1310 + 1e-4 && x.z() > 0.0546 - 1e-4 &&
                x.z() < 0.0654 + 1e-4);
  }
  // Sorted 0-based: the smallest id in the file is 17, the first one 363.
  EXPECT_EQ(mesh.nodeSets.at("jaw").front(), 16);
  EXPECT_TRUE(std::binary_search(mesh.nodeSets.at("jaw").begin(), mesh.nodeSets.at("jaw").end(), 362));
}

// A unit cube as two stacked hexes, ids starting at 101/7 to exercise the id maps.
const std::string kNodes =
    "101 0 0 0\n102 1 0 0\n103 1 1 0\n104 0 1 0\n105 0 0 1\n106 1 0 1\n107 1 1 1\n108 0 1 1\n"
    "109 0 0 2\n110 1 0 2\n111 1 1 2\n112 0 1 2";
const std::string kElem1 = "101 102 103 104 105 106 107 108 1 1 1 1 0 7";
const std::string kElem2 = "105 106 107 108 109 110 111 112 1 1 1 1 0 8";

TEST(AnsysReader, AcceptsCrlfLatin1AndNoFinalNewline) {
  ScratchDir dir("ansys_quirks");
  const std::string nodes = dir.write("a.node", "! commentaire g\xe9n\xe9ral\r\n" + kNodes);
  const std::string elems = dir.write("a.elem", kElem1 + "\r\n" + kElem2);
  const std::string mac = dir.write(
      "a.mac",
      "! D\xe9"
      "finition\r\n*DIM,muscleName,CHAR,2\r\nmuscleName(1) = 'LOW'\r\nmuscleName(2)= 'BOTH'\r\n"
      "ESEL,S,ELEM,,7\r\nCM,LOW,ELEM \r\nESEL,S,ELEM,,7,8\r\nESEL,U,ELEM,,8\r\nESEL,A,ELEM,,7,8,1\r\n"
      "CM,BOTH,ELEM\t! tout");
  ImportedMesh imported = readAnsysMesh(nodes, elems);
  EXPECT_EQ(imported.mesh.numNodes(), 12u);
  EXPECT_EQ(imported.nodeOfFileId(109), 8);
  EXPECT_EQ(imported.elementOfFileId(8), 1);
  EXPECT_NEAR(meshVolume(imported.mesh), 2.0, 1e-14);
  const AnsysComponents c = readAnsysComponents(mac, imported);
  EXPECT_EQ(c.names, (std::vector<std::string>{"LOW", "BOTH"}));
  EXPECT_EQ(imported.mesh.elementSets.at("LOW"), std::vector<ElementId>{0});
  EXPECT_EQ(imported.mesh.elementSets.at("BOTH"), (std::vector<ElementId>{0, 1}));
}

TEST(AnsysReader, RefusesMalformedMeshFiles) {
  ScratchDir dir("ansys_bad");
  const std::string nodes = dir.write("n", kNodes);
  const std::string goodElems = dir.write("e", kElem1 + "\n" + kElem2 + "\n");
  auto elems = [&](const std::string &second) {
    const std::string e = dir.write("bad.elem", kElem1 + "\n" + second + "\n");
    return [nodes, e] { readAnsysMesh(nodes, e); };
  };
  const std::string e = dir.file("bad.elem");
  expectError(elems("105 106 107 108 109 110 111 112 1 1 1 1 0"), {e + ":2:", "14 integers", "found 13"});
  expectError(elems("105 106 107 108 109 110 111 11x 1 1 1 1 0 8"), {e + ":2:", "bad node id '11x'"});
  expectError(elems("105 106 107 108 109 110 111 999 1 1 1 1 0 8"), {e + ":2:", "element 8", "node 999"});
  expectError(elems("105 106 107 108 109 110 111 112 1 1 1 1 0 7"), {e + ":2:", "duplicate element id 7"});
  expectError(elems("105 106 107 108 109 110 111 109 1 1 1 1 0 8"), {e + ":2:", "element 8 repeats a node"});
  // Top and bottom swapped: a mirror image, negative Jacobian everywhere.
  expectError(elems("109 110 111 112 105 106 107 108 1 1 1 1 0 8"), {e + ":2:", "element 8 is inverted"});
  // A flat element: top face on the bottom face's plane.
  const std::string flatNodes =
      dir.write("flat.node", kNodes + "\n113 0 0 1\n114 1 0 1\n115 1 1 1\n116 0 1 1.0");
  const std::string flat = dir.write("flat.elem", kElem1 + "\n105 106 107 108 113 114 115 116 1 1 1 1 0 8");
  expectError([&] { readAnsysMesh(flatNodes, flat); }, {flat + ":2:", "element 8 is inverted or degenerate"});

  const std::string dupNode = dir.write("dup.node", kNodes + "\n101 5 5 5\n");
  expectError([&] { readAnsysMesh(dupNode, goodElems); }, {dupNode + ":13:", "duplicate node id 101"});
  const std::string badX = dir.write("badx.node", "1 0 0 nan\n");
  expectError([&] { readAnsysMesh(badX, goodElems); }, {badX + ":1:", "bad coordinate 'nan'"});
  const std::string shortNode = dir.write("short.node", "1 0 0\n");
  expectError([&] { readAnsysMesh(shortNode, goodElems); }, {shortNode + ":1:", "expected 'id x y z'"});
  expectError([&] { readAnsysMesh(dir.file("missing"), goodElems); }, {"missing: cannot open"});
}

TEST(AnsysReader, RefusesMalformedMacros) {
  ScratchDir dir("ansys_bad_mac");
  ImportedMesh imported = readAnsysMesh(dir.write("n", kNodes), dir.write("e", kElem1 + "\n" + kElem2));
  auto macro = [&](const std::string &text) {
    const std::string m = dir.write("m.mac", text);
    return [m, &imported] { readAnsysComponents(m, imported); };
  };
  const std::string m = dir.file("m.mac");
  expectError(macro("ESEL,S,ELEM,,7\nESEL,A,ELEM,,9\n"), {m + ":2:", "element 9 is not in the mesh"});
  expectError(macro("muscleName(1) = 'A'\nESEL,S,ELEM,,7\nCM,B,ELEM\n"), {m + ":3:", "muscleName(1) = 'A'"});
  expectError(macro("ESEL,S,ELEM,,7,8,0\n"), {m + ":1:", "increment must be positive"});
  expectError(macro("ESEL,S,ELEM,,7\nNSEL,S,NODE,,1\n"), {m + ":2:", "unsupported APDL command 'NSEL'"});
  expectError(macro("ESEL,S,ELEM,,7\nCM,A,ELEM\nCMGRP,G,A,C\n"), {m + ":3:", "'C' is not a component"});

  const std::map<std::int64_t, Eigen::Vector3d> anchors = {{4037, Eigen::Vector3d(9, 9, 9)}};
  auto fibres = [&](const std::string &text) {
    const std::string f = dir.write("f.mac", text);
    return [f, &imported, anchors] { readAnsysFibres(f, imported, {"A"}, anchors); };
  };
  const std::string f = dir.file("f.mac");
  const std::string ok = "NB_FIBERS(1)=1\nNB_NODES_FIBER(1,1)=3\nFIBER(1,1,1)=101\nFIBER(2,1,1)=112\n";
  const std::string okFile = dir.write("ok.mac", ok + "FIBER(3,1,1)=4037");
  const auto read = readAnsysFibres(okFile, imported, {"A"}, anchors);
  ASSERT_EQ(read.size(), 1u);
  ASSERT_EQ(read[0].fibres.size(), 1u);
  EXPECT_EQ(read[0].fibres[0][1].node, 11);
  EXPECT_EQ(read[0].fibres[0][2].node, -1);
  EXPECT_EQ(read[0].fibres[0][2].position, Eigen::Vector3d(9, 9, 9));
  expectError(fibres(ok + "FIBER(3,1,1)=4042\n"), {f + ":5:", "node 4042 is neither a mesh node"});
  expectError(fibres(ok), {f + ":2:", "NB_NODES_FIBER = 3", "nodes 1..2"});
  expectError(fibres(ok + "FIBER(3,1,2)=101\n"), {f + ":5:", "muscle index 2 outside 1..1"});
  expectError(fibres("NB_FIBERS(1)=2\nNB_NODES_FIBER(1,1)=2\nFIBER(1,1,1)=101\nFIBER(2,1,1)=112\n"),
              {f + ":1:", "NB_FIBERS = 2"});

  const std::string list = dir.write("l.txt", "101\n102 999\n");
  expectError([&] { readAnsysNodeList(list, "x", imported); }, {list + ":2:", "node 999 is not in the mesh"});
}

}  // namespace
}  // namespace glossa::mesh
