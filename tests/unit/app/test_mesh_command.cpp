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
#include "mesh/MeshQuality.hpp"
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

// One interior node of the 2 x 2 x 2 box moved towards a corner: the elements around it lose
// their right angles, the worst first, named in the report with their scaled Jacobians.
TEST(MeshCommand, NamesTheElementsOfTheSmallestScaledJacobian) {
  mesh::HexMesh box = mesh::generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 2, 3), {2, 2, 2});
  std::size_t centre = 0;
  for (std::size_t n = 0; n < box.nodes.size(); ++n)
    if ((box.nodes[n] - Eigen::Vector3d(0.5, 1.0, 1.5)).norm() < 1e-12) centre = n;
  box.nodes[centre] += Eigen::Vector3d(0.15, 0.3, 0.45);  // 30 % of the way to the corner (1, 2, 3)
  const std::string file = (test::processScratch() / "mesh_command_skewed.msh").string();
  mesh::writeGmsh(box, file);
  const nlohmann::json r = describeMesh(file, {});
  const auto &worst = r.at("scaled_jacobian").at("worst");
  ASSERT_EQ(worst.size(), 5u);
  EXPECT_DOUBLE_EQ(worst[0].at("value").get<double>(), r.at("scaled_jacobian").at("min").get<double>());
  for (std::size_t k = 1; k < worst.size(); ++k)
    EXPECT_LE(worst[k - 1].at("value").get<double>(), worst[k].at("value").get<double>());
  // The worst is the element at the far corner, whose own corner the node now nearly reaches.
  const auto e = static_cast<mesh::ElementId>(worst[0].at("element").get<std::size_t>());
  const auto &hex = box.elements[static_cast<std::size_t>(e)];
  bool hasFarCorner = false;
  for (const auto n : hex) hasFarCorner |= (box.nodes[static_cast<std::size_t>(n)] - Eigen::Vector3d(1, 2, 3)).norm() < 1e-12;
  EXPECT_TRUE(hasFarCorner);
  EXPECT_NEAR(worst[0].at("value").get<double>(), mesh::scaledJacobian(box.elementCoordinates(e)), 1e-14);
  EXPECT_NE(meshReportText(r).find("smallest at elements (numbered from 0) " + std::to_string(static_cast<std::size_t>(e))),
            std::string::npos);
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
