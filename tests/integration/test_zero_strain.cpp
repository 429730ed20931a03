// s8_1 (paper §8.1, Fig. 7a): the zero-strain configuration of the tongue under upright gravity.
// glossa zero-strain computes it by the paper's approximation (1.2 g reversed on the imaged
// geometry) and by the iterative inverse; upright gravity on each must return the imaged
// geometry, the inverse to its tolerance and at least 10 times closer than the approximation
// (doc/tongue.md, s8_1). The reference is independent of the command: the imaged geometry is the mesh file
// read directly, and the check is a separate run of the s8_1 deck with the written coordinates
// file, its displacement taken from the solver.
// CI-cheap: the tongue's 740 elements, gravity in one load step (the deck has four), at most
// four inverse updates (it needs three), no field output: about 7 s in all.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "RunDeck.hpp"
#include "app/ZeroStrainCommand.hpp"
#include "mesh/MeshFile.hpp"
#include "mesh/MeshQuality.hpp"
#include "mesh/MeshRefinement.hpp"
#include "mesh/ReferenceCoordinates.hpp"
#include "input/SceneFactory.hpp"
#include "io/deck/DeckError.hpp"
#include "solvers/parameters/ControlSection.hpp"
#include "solvers/parameters/RunConfiguration.hpp"

namespace glossa::test {
namespace {

const std::vector<std::string> kCheap{"Time/step size=1", "Output/fields=false",
                                      "Zero strain/maximum iterations=4"};

struct Distances {
  double max = 0.0, mean = 0.0;
};

// Upright gravity (the s8_1 deck) on the reference in `coordinates`: the distance of every node
// from the imaged geometry of inputs/tongue/tongue.node.
Distances gravityOn(const std::filesystem::path &coordinates, const std::filesystem::path &output) {
  const auto schema = app::deckSchema();
  auto deck = io::Deck::fromFile(inputPath("paper/s8_1_upright.xml"));
  for (const auto &o : kCheap) deck.applyOverride(o, schema);
  deck.applyOverride("Mesh/reference coordinates file=" + coordinates.string(), schema);
  deck.validate(schema);
  std::vector<double> u;
  const auto summary = solvers::runSimulation(deck, solvers::parseRunConfiguration(deck), test::worldComm(),
                                              {output, true, false, 1, &u});
  EXPECT_TRUE(summary.value("converged", false));
  const auto imaged = mesh::readMeshFile(inputPath("tongue/tongue.node")).mesh.nodes;
  EXPECT_EQ(u.size(), 3 * imaged.size());
  // The coordinates file, read back independently of the solver: "node x y z" lines.
  std::ifstream in(coordinates);
  std::string line;
  std::vector<Eigen::Vector3d> X(imaged.size());
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::size_t n;
    double x, y, z;
    s >> n >> x >> y >> z;
    X.at(n) = {x, y, z};
  }
  Distances d;
  for (std::size_t n = 0; n < imaged.size(); ++n) {
    const double r = (X[n] + Eigen::Vector3d(u[3 * n], u[3 * n + 1], u[3 * n + 2]) - imaged[n]).norm();
    d.max = std::max(d.max, r);
    d.mean += r / static_cast<double>(imaged.size());
  }
  return d;
}

app::ZeroStrainResult zeroStrain(const std::string &method, const std::filesystem::path &output) {
  const auto schema = app::deckSchema();
  auto deck = io::Deck::fromFile(inputPath("paper/s8_1_upright.xml"));
  for (const auto &o : kCheap) deck.applyOverride(o, schema);
  deck.applyOverride("Zero strain/method=" + method, schema);
  deck.validate(schema);
  return app::computeZeroStrain(deck, solvers::parseRunConfiguration(deck), test::worldComm(), output, true);
}

// The coarse tongue's zero-strain configuration on the refined tongue (Mesh/File/refine = 1): the
// old nodes where the file puts them, the imaged geometry that of the refined mesh file, and the
// reference volume the coarse reference's (refinement keeps the trilinear elements' volume), at
// one level and at two.
TEST(ZeroStrain, TheCoarseConfigurationCarriesToTheRefinedTongue) {
  const auto schema = app::deckSchema();
  const auto file = inputPath("paper/s8_1/reference_inverse.txt");
  auto deck = io::Deck::fromFile(inputPath("paper/s8_1_upright.xml"));
  deck.applyOverride("Mesh/reference coordinates file=" + file, schema);
  deck.applyOverride("Mesh/File/refine=1", schema);
  deck.validate(schema);
  const model::Scene scene = input::buildScene(deck, 1.0);
  const mesh::HexMesh imaged = mesh::readMeshFile(inputPath("tongue/tongue.node")).mesh;
  const auto X = mesh::readReferenceCoordinates(file, imaged.numNodes());
  ASSERT_EQ(scene.mesh.numNodes(), mesh::refineUniformly(imaged, 1).numNodes());
  for (std::size_t n = 0; n < X.size(); ++n) EXPECT_EQ(scene.mesh.nodes[n], X[n]) << n;
  EXPECT_EQ(scene.mesh.imagedNodes, mesh::refineUniformly(imaged, 1).nodes);
  mesh::HexMesh coarseReference = imaged;
  coarseReference.nodes = X;
  const double V = mesh::meshVolume(coarseReference);
  EXPECT_NEAR(mesh::meshVolume(scene.mesh), V, 1e-12 * V);
  double largestMove = 0.0;  // the reference is not the imaged mesh (its volume is, nearly: J = 1)
  for (std::size_t n = 0; n < X.size(); ++n) largestMove = std::max(largestMove, (X[n] - imaged.nodes[n]).norm());
  EXPECT_GT(largestMove, 1e-3);

  // Refined twice, the same file is carried through both levels.
  deck.applyOverride("Mesh/File/refine=2", schema);
  const model::Scene twice = input::buildScene(deck, 1.0);
  EXPECT_EQ(twice.mesh.numNodes(), mesh::refineUniformly(imaged, 2).numNodes());
  EXPECT_NEAR(mesh::meshVolume(twice.mesh), V, 1e-12 * V);

  // A file that fits neither mesh: the refusal names both counts.
  const auto dir = scratchDirectory("zero_strain_refined");
  std::filesystem::create_directories(dir);
  const auto wrong = dir / "three_nodes.txt";
  std::ofstream(wrong) << "0 0 0 0\n1 1 0 0\n2 0 1 0\n";
  deck.applyOverride("Mesh/reference coordinates file=" + wrong.string(), schema);
  try {
    input::buildScene(deck, 1.0);
    ADD_FAILURE() << "a file of neither mesh's node count was accepted";
  } catch (const io::DeckError &e) {
    EXPECT_NE(std::string(e.what()).find("3 nodes, but the mesh has "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("(or 946, the mesh's before Mesh/File/refine)"), std::string::npos)
        << e.what();
  }
}

TEST(ZeroStrain, InverseReturnsTheImagedGeometryTenTimesCloserThanTheApproximation) {
  const auto dir = scratchDirectory("zero_strain");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto a = zeroStrain("approximate", dir / "approximate.txt");
  const auto b = zeroStrain("inverse", dir / "inverse.txt");
  ASSERT_TRUE(a.converged);
  ASSERT_TRUE(b.converged) << "max distance " << b.maxDistance << " m after " << b.iterations
                           << " iterations";

  const Distances da = gravityOn(dir / "approximate.txt", dir / "check_approximate");
  const Distances db = gravityOn(dir / "inverse.txt", dir / "check_inverse");
  // The command's own figures are those of an independent run from its file (same solve, so to
  // the file's 17 digits and the solver's round-off).
  EXPECT_NEAR(da.max, a.maxDistance, 1e-9);
  EXPECT_NEAR(db.max, b.maxDistance, 1e-9);
  EXPECT_NEAR(db.mean, b.meanDistance, 1e-9);

  // The tolerance: 1e-3 of the mean element edge of the imaged mesh (the s8_1 deck).
  EXPECT_NEAR(b.tolerance, 1e-3 * b.meshSize, 1e-15);
  EXPECT_GT(b.meshSize, 1e-3);  // the tongue's elements are millimetres across
  EXPECT_LE(db.max, b.tolerance);
  // The inverse is worth its cost: at least 10 times closer than the 1.2 g approximation (max and
  // mean distance).
  EXPECT_GE(da.max, 10.0 * db.max) << "approximate " << da.max << " m, inverse " << db.max << " m";
  EXPECT_GE(da.mean, 10.0 * db.mean) << "approximate " << da.mean << " m, inverse " << db.mean << " m";
  // Gravity itself moves the imaged tongue by millimetres: the approximation is not a trivial one.
  EXPECT_GT(a.history.at(0).at("max_distance").get<double>(), 1e-3);
  EXPECT_GT(da.max, 1e-4);
  RecordProperty("approximate_max_um", std::to_string(da.max * 1e6));
  RecordProperty("inverse_max_um", std::to_string(db.max * 1e6));
}

// On the zero-strain configuration the traces measure each point twice: u from X0 and
// d = X0 + u - X_img from where it was imaged, and the control goals are the imaged positions.
// Gravity on the stored inverse X0 (s8_1_inverse.xml) returns the imaged geometry to 3.6 um
// (the test above checks the same file independently), so d must vanish at the end while u is
// millimetres; at t = 0, d is X0 - X_img, millimetres too.
TEST(ZeroStrain, TracesAndControlGoalsMeasureFromTheImagedGeometry) {
  const auto dir = scratchDirectory("zero_strain_traces");
  std::filesystem::remove_all(dir);
  const auto summary = runDeck(inputPath("paper/s8_1_inverse.xml"), {"Time/step size=1", "Output/fields=false"}, dir);
  ASSERT_TRUE(summary.value("converged", false));
  const auto rows = readTraces(dir / "traces.csv");
  const double mesh = 5.70e-3; // the mean element edge of the imaged tongue (the test above)
  int points = 0;
  for (const auto &r : rows) {
    const Eigen::Vector3d u(r.u[0], r.u[1], r.u[2]), d(r.d[0], r.d[1], r.d[2]);
    if (r.time == 0.0) {
      EXPECT_EQ(u.norm(), 0.0) << r.point;
      if (r.point == "P_A") {
        EXPECT_GT(d.norm(), 1e-3) << "X0 - X_img at the tip";
      }
    } else {
      ++points;
      EXPECT_LE(d.norm(), 1e-3 * mesh) << r.point << " at t = " << r.time;
      if (r.point == "P_A") {
        EXPECT_GT(u.norm(), 4e-3) << "gravity moves the tip from X0 by millimetres";
      }
    }
  }
  EXPECT_EQ(points, 12); // P_A, P_P and C01-C10 at t = 1

  // The controlled deck on the same X0: its goals are the imaged nodes of tongue.node.
  const auto schema = app::deckSchema();
  auto deck = io::Deck::fromFile(inputPath("paper/s8_5_gradient_upright.xml"));
  deck.validate(schema);
  const model::Scene scene = input::buildScene(deck, 8.75);
  const solvers::ControlSetup control = solvers::buildControl(deck, scene);
  const auto imaged = mesh::readMeshFile(inputPath("tongue/tongue.node")).mesh.nodes;
  ASSERT_EQ(control.pointNodes.size(), 10u);
  for (std::size_t p = 0; p < control.pointNodes.size(); ++p) {
    const auto n = static_cast<std::size_t>(control.pointNodes[p]);
    EXPECT_EQ((control.goals.col(static_cast<Eigen::Index>(p)) - imaged[n]).norm(), 0.0) << control.pointNames[p];
    EXPECT_GT((scene.mesh.nodes[n] - imaged[n]).norm(), 1e-5) << control.pointNames[p] << " (X0 is not X_img)";
  }
}

}  // namespace
}  // namespace glossa::test
