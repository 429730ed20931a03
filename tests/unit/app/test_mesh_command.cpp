// glossa mesh on a box written as a Gmsh file: the report's counts, volume, quality, checks and
// sets are the box's; --refine splits every hexahedron into eight; --output OUT.inp writes a mesh
// that reads back the same, an --output of another format is refused; the text report says the
// same numbers.
#include <filesystem>

#include <gtest/gtest.h>

#include "ProcessScratch.hpp"

#include "app/MeshCommand.hpp"
#include "io/deck/DeckError.hpp"
#include "mesh/BoxGenerator.hpp"
#include "mesh/MeshWriter.hpp"

namespace glossa::app {
namespace {

// A 1 x 2 x 3 m box of 2 x 2 x 2 cells: 27 nodes, 8 elements, 6 m^3.
std::string boxFile() {
  const std::string file = (test::processScratch() / "mesh_command_box.msh").string();
  mesh::writeGmsh(mesh::generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 2, 3), {2, 2, 2}), file);
  return file;
}

TEST(MeshCommand, ReportsTheBoxsCountsVolumeQualityAndSets) {
  const nlohmann::json r = describeMesh(boxFile(), {});
  EXPECT_EQ(r.at("nodes"), 27);
  EXPECT_EQ(r.at("elements"), 8);
  EXPECT_NEAR(r.at("volume").get<double>(), 6.0, 1e-12);
  EXPECT_NEAR(r.at("scaled_jacobian").at("min").get<double>(), 1.0, 1e-12); // right-angled corners
  EXPECT_NEAR(r.at("scaled_jacobian").at("max").get<double>(), 1.0, 1e-12);
  for (const char *check : {"unused_nodes", "coincident_node_pairs", "duplicate_elements", "inverted_corner_elements"})
    EXPECT_EQ(r.at("checks").at(check), 0) << check;
  EXPECT_EQ(r.at("checks").at("parts"), 1);
  EXPECT_EQ(r.at("sets").at("face").at("xmin").at("size"), 4);  // 2 x 2 faces
  EXPECT_EQ(r.at("sets").at("face").at("zmax").at("size"), 4);
  EXPECT_FALSE(r.contains("written"));
}

TEST(MeshCommand, RefiningSplitsEveryHexahedronInEight) {
  const nlohmann::json r = describeMesh(boxFile(), {"auto", 1, {}});
  EXPECT_EQ(r.at("refine"), 1);
  EXPECT_EQ(r.at("nodes"), 125);
  EXPECT_EQ(r.at("elements"), 64);
  EXPECT_NEAR(r.at("volume").get<double>(), 6.0, 1e-12);
  EXPECT_EQ(r.at("sets").at("face").at("xmin").at("size"), 16);
}

TEST(MeshCommand, AnAbaqusFileWrittenReadsBackTheSame) {
  const std::filesystem::path inp = test::processScratch() / "mesh_command_box.inp";
  std::filesystem::remove(inp);
  const nlohmann::json written = describeMesh(boxFile(), {"auto", 0, inp});
  EXPECT_EQ(written.at("written"), inp.string());
  const nlohmann::json back = describeMesh(inp.string(), {});
  EXPECT_EQ(back.at("nodes"), written.at("nodes"));
  EXPECT_EQ(back.at("elements"), written.at("elements"));
  EXPECT_NEAR(back.at("volume").get<double>(), 6.0, 1e-12);
  EXPECT_EQ(back.at("sets").at("face"), written.at("sets").at("face"));
}

TEST(MeshCommand, AnOutputOfAnotherFormatIsRefusedNotMadeADirectory) {
  const std::filesystem::path dir = test::processScratch() / "mesh_command_output";
  std::filesystem::remove_all(dir);
  try {
    describeMesh(boxFile(), {"auto", 0, dir / "out.vtk"});
    ADD_FAILURE() << "out.vtk accepted";
  } catch (const io::DeckError &e) {
    EXPECT_NE(std::string(e.what()).find("not .vtk files"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out.vtk"));
  // A directory of that name, said with a trailing / or existing already, takes the XDMF.
  EXPECT_EQ(describeMesh(boxFile(), {"auto", 0, dir / "out.vtk/"}).at("written"), (dir / "out.vtk/mesh.xdmf").string());
  EXPECT_EQ(describeMesh(boxFile(), {"auto", 0, dir / "out.vtk"}).at("written"), (dir / "out.vtk/mesh.xdmf").string());
}

TEST(MeshCommand, TheTextReportSaysTheSame) {
  const std::string text = meshReportText(describeMesh(boxFile(), {}));
  EXPECT_NE(text.find("nodes 27  elements 8  volume 6 m^3"), std::string::npos) << text;
  EXPECT_NE(text.find("scaled Jacobian 1 .. 1"), std::string::npos) << text;
  EXPECT_NE(text.find("parts 1  unused nodes 0"), std::string::npos) << text;
  EXPECT_NE(text.find("face set xmin: 4"), std::string::npos) << text;
}

} // namespace
} // namespace glossa::app
