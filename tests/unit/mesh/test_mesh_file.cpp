// The format dispatch: extensions, explicit formats, errors.

#include <gtest/gtest.h>

#include "ImportTestSupport.hpp"
#include "mesh/MeshFile.hpp"

namespace glossa::mesh {
namespace {

using testing::expectError;

TEST(MeshFile, FormatFromExtension) {
  EXPECT_EQ(meshFormatOfPath("a/b.msh"), "gmsh");
  EXPECT_EQ(meshFormatOfPath("a/b.INP"), "abaqus");
  EXPECT_EQ(meshFormatOfPath("a/tongue.node"), "ansys");
  EXPECT_EQ(meshFormatOfPath("tongue.elem"), "ansys");
  expectError([] { meshFormatOfPath("dir.v2/mesh"); }, {"dir.v2/mesh", "cannot tell the mesh format"});
  expectError([] { meshFormatOfPath("m.vtk"); }, {"'.vtk'"});
}

TEST(MeshFile, ReadsEachFormat) {
  const std::string dir = std::string(GLOSSA_SOURCE_DIR) + "/inputs/tongue/";
  // The ANSYS pair from either file.
  EXPECT_EQ(readMeshFile(dir + "tongue.node").mesh.numElements(), 740u);
  EXPECT_EQ(readMeshFile(dir + "tongue.elem", "ansys").mesh.numNodes(), 946u);
  testing::ScratchDir scratch("mesh_file");
  const std::string inp =
      scratch.write("cube.txt",
                    "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n8,0,1,1\n"
                    "*ELEMENT, TYPE=C3D8\n1,1,2,3,4,5,6,7,8\n");
  EXPECT_EQ(readMeshFile(inp, "abaqus").mesh.numElements(), 1u);
  expectError([&] { readMeshFile(inp, "gmsh"); }, {inp + ":1:", "expected a section header"});
  expectError([&] { readMeshFile(inp, "vtk"); }, {"unknown mesh format 'vtk'", "abaqus, ansys, gmsh"});
}

}  // namespace
}  // namespace glossa::mesh
