// Moved nodes (Mesh/File/moved nodes): a mesh file kept as published with some nodes moved.

#include <gtest/gtest.h>

#include "ImportTestSupport.hpp"
#include "mesh/MeshFile.hpp"
#include "mesh/MeshQuality.hpp"
#include "mesh/MovedNodes.hpp"

namespace glossa::mesh {
namespace {

using testing::expectError;

ImportedMesh unitCube(testing::ScratchDir &scratch) {
  const std::string inp =
      scratch.write("cube.inp",
                    "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
                    "*ELEMENT, TYPE=C3D8\n1,1,2,3,4,5,6,7,8\n");
  return readMeshFile(inp);
}

TEST(MovedNodes, MoveTheNamedNodesOnly) {
  testing::ScratchDir scratch("moved_nodes");
  ImportedMesh cube = unitCube(scratch);
  // Node 7 (1, 1, 1) pulled out to (1.5, 1.5, 1.5).
  moveNodes(scratch.write("m.txt", "# moved\n7 1.5 1.5 1.5  ! the far corner\n\n"), cube);
  EXPECT_EQ(cube.mesh.nodes[cube.nodeOfFileId(7)], Eigen::Vector3d(1.5, 1.5, 1.5));
  EXPECT_EQ(cube.mesh.nodes[cube.nodeOfFileId(1)], Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(cube.mesh.nodes[cube.nodeOfFileId(8)], Eigen::Vector3d(0, 1, 1));
  // x = X + N_7 d with N_7 = xi eta zeta and d = (a, a, a): dx/dX = I + d (grad N_7)^T, a rank-one
  // update, so det = 1 + a (eta zeta + xi zeta + xi eta), whose mean over the cube is 1 + 3a/4.
  EXPECT_NEAR(meshVolume(cube.mesh), 1.0 + 0.75 * 0.5, 1e-14);
}

TEST(MovedNodes, RefusesABadFileNamingItsLine) {
  testing::ScratchDir scratch("moved_nodes_errors");
  auto tryFile = [&scratch](const std::string &name, const std::string &text) {
    const std::string path = scratch.write(name, text);
    return [path, &scratch] {
      ImportedMesh cube = unitCube(scratch);
      moveNodes(path, cube);
    };
  };
  expectError(tryFile("a.txt", "7 1 1\n"), {"a.txt:1:", "expected 'id x y z'"});
  expectError(tryFile("b.txt", "7 1 1 1\n9 0 0 0\n"), {"b.txt:2:", "node 9 is not in the mesh"});
  expectError(tryFile("c.txt", "7 1 1 1\n7 1 1 1\n"), {"c.txt:2:", "node 7 is moved twice"});
  expectError(tryFile("d.txt", "7 1 x 1\n"), {"d.txt:1:", "'x' is not a coordinate"});
  expectError(tryFile("e.txt", "# nothing\n"), {"e.txt", "no moved nodes"});
  // Node 7 pushed through the opposite corner turns the element inside out.
  expectError(tryFile("f.txt", "7 -1 -1 -1\n"), {"f.txt", "with these nodes moved"});
}

// The mended tongue (inputs/tongue/mend_tongue.py): only interior nodes move, so the surface and
// the volume are the published mesh's, and the worst element is at least three times better.
TEST(MovedNodes, TheMendedTongueKeepsItsSurfaceAndVolume) {
  const std::string dir = std::string(GLOSSA_SOURCE_DIR) + "/inputs/tongue/";
  const ImportedMesh published = readMeshFile(dir + "tongue.node");
  ImportedMesh mended = readMeshFile(dir + "tongue.node");
  moveNodes(dir + "tongue_mended_nodes.txt", mended);
  std::size_t moved = 0;
  for (std::size_t n = 0; n < published.mesh.numNodes(); ++n)
    if (published.mesh.nodes[n] != mended.mesh.nodes[n]) ++moved;
  EXPECT_EQ(moved, 93u);
  for (const ElementFace &f : boundaryFaces(published.mesh))
    for (int local : kHexFaceNodes[static_cast<std::size_t>(f.localFace)]) {
      const NodeId n = published.mesh.elements[f.element][static_cast<std::size_t>(local)];
      EXPECT_EQ(published.mesh.nodes[n], mended.mesh.nodes[n]);
    }
  // Moving interior nodes leaves the volume the boundary encloses (the trilinear elements'
  // volumes sum to the volume inside the bilinear surface).
  EXPECT_NEAR(meshVolume(mended.mesh), meshVolume(published.mesh), 1e-12 * meshVolume(published.mesh));
  EXPECT_GT(scaledJacobianRange(mended.mesh).first, 3.0 * scaledJacobianRange(published.mesh).first);
}

}  // namespace
}  // namespace glossa::mesh
