// Run under mpiexec -np 2: the same deck on one rank (a split communicator) and on both ranks
// gives the same displacement field (every node, read from the last step file) to 1e-8 relative, for
// the penalty, augmented-Lagrangian, mixed and FROSch paths; and the contact patch block at the
// default solver settings (an iterative solve on 2 ranks): fixed components exactly at their
// prescribed values, the contact pressure the applied one; the two-block patch with its blocks on
// different ranks.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "LastStepField.hpp"
#include "RunDeck.hpp"
#include "io/deck/DeckError.hpp"
#include "Hdf5Reading.hpp"
#include "io/deck/Deck.hpp"
#include "mesh/AbaqusReader.hpp"
#include "mesh/BoxGenerator.hpp"
#include "mesh/Partition.hpp"

using namespace glossa;

namespace {
// The whole displacement field of the last written step, by mesh node.
std::vector<double> finalField(const std::filesystem::path &dir) { return test::lastStepField(dir, "displacement"); }

void expectSameOnOneAndTwoRanks(const std::vector<std::string> &overrides, const std::string &tag) {
  auto world = test::worldComm();
  ASSERT_EQ(world->getSize(), 2) << "run this test with mpiexec -np 2";
  const int rank = world->getRank();
  auto single = world->split(rank, 0); // each rank alone
  const auto dirSerial = test::scratchDirectory("mpi_serial_" + tag);
  const auto dirParallel = test::scratchDirectory("mpi_parallel_" + tag);
  if (rank == 0) test::runDeck(test::inputPath("verification/step44_block.xml"), overrides, dirSerial, single);
  world->barrier();
  const auto parallel = test::runDeck(test::inputPath("verification/step44_block.xml"), overrides, dirParallel, world);
  EXPECT_EQ(parallel.at("ranks").get<int>(), 2);
  if (rank != 0) return;
  const auto a = finalField(dirSerial), b = finalField(dirParallel);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.size(), 3u * 7 * 7 * 7);
  double scale = 0.0, diff = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    scale = std::max(scale, std::abs(a[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
  }
  EXPECT_LT(diff, 1e-8 * scale) << "max difference " << diff << " of " << scale;
  std::printf("max |u_1 - u_2| = %.3e of max |u| = %.3e\n", diff, scale);
}
} // namespace

TEST(MpiConsistency, PenaltyOneAndTwoRanksAgree) {
  expectSameOnOneAndTwoRanks({"Mesh/Box/cells=6,6,6", "Linear solver/type=iterative", "Linear solver/tolerance=1e-10", "Nonlinear solver/forcing term=constant"},
                             "penalty");
}

TEST(MpiConsistency, AugmentedLagrangianOneAndTwoRanksAgree) {
  expectSameOnOneAndTwoRanks({"Mesh/Box/cells=6,6,6", "Linear solver/type=iterative", "Linear solver/tolerance=1e-10",
                              "Nonlinear solver/forcing term=constant", "Incompressibility/method=augmented Lagrangian"},
                             "al");
}

// The mixed block solve (pressures as unknowns) at exact incompressibility, nu = 0.5.
TEST(MpiConsistency, MixedOneAndTwoRanksAgree) {
  expectSameOnOneAndTwoRanks({"Mesh/Box/cells=6,6,6", "Linear solver/type=iterative", "Linear solver/tolerance=1e-10",
                              "Nonlinear solver/forcing term=constant", "Incompressibility/method=mixed",
                              "Material/Poisson's ratio=0.5"},
                             "mixed");
}

// FROSch: one subdomain per rank, so 1 and 2 ranks are different preconditioners (a direct solve
// against two-level additive Schwarz); converged to 1e-10 they must still give the same field.
TEST(MpiConsistency, FroschOneAndTwoRanksAgree) {
  expectSameOnOneAndTwoRanks({"Mesh/Box/cells=6,6,6", "Linear solver/type=iterative", "Linear solver/tolerance=1e-10",
                              "Nonlinear solver/forcing term=constant", "Linear solver/preconditioner=FROSch"},
                             "frosch");
}

// The MUMPS direct solve with each rank's rows given distributed (ICNTL(18) = 3) and the
// right-hand side gathered on rank 0: the same field as on one rank.
TEST(MpiConsistency, DirectOneAndTwoRanksAgree) {
  expectSameOnOneAndTwoRanks({"Mesh/Box/cells=6,6,6", "Linear solver/type=direct", "Nonlinear solver/forcing term=constant",
                              "Incompressibility/method=augmented Lagrangian"},
                             "direct");
}

// The vertex-patch smoother is refused on more than one rank (its patches are cut at the partition
// boundary and CG broke down: 8,067 Krylov iterations and a failed step at t = 0.59 on 6^3).
TEST(MpiConsistency, VertexPatchIsRefusedOnTwoRanks) {
  EXPECT_THROW(test::runDeck(test::inputPath("verification/step44_block.xml"),
                             {"Mesh/Box/cells=2,2,2", "Linear solver/type=iterative",
                              "Linear solver/MueLu smoother=vertex-patch"},
                             test::scratchDirectory("mpi_patch_refused"), test::worldComm()),
               io::DeckError);
}

// The contact patch block (inputs/verification/contact_patch_block.xml), 1 rank at its default
// solver settings (directly), 2 ranks iteratively: on 2 ranks the fixed components
// (x at xmin, y at ymin) are exactly 0, every traced bottom node sinks by p / eps (the plane
// carries the applied pressure p, the penalty law's contact pressure) to 1e-6, and the field agrees
// with one rank's to 1e-8. Before the residual ignored what an iterate held at fixed dofs, MueLu's
// ~1e-9 m there moved the supports (uy = -3e-9 m at the bottom edge), the field differed by 3.5e-4
// and the contact pressure by 1.7e-5.
TEST(MpiConsistency, ContactPatchHoldsFixedComponentsExactlyOnTwoRanks) {
  auto world = test::worldComm();
  ASSERT_EQ(world->getSize(), 2) << "run this test with mpiexec -np 2";
  const int rank = world->getRank();
  auto single = world->split(rank, 0);
  const std::string deck = test::inputPath("verification/contact_patch_block.xml");
  const auto dirSerial = test::scratchDirectory("mpi_serial_contact"), dirParallel = test::scratchDirectory("mpi_parallel_contact");
  if (rank == 0) test::runDeck(deck, {}, dirSerial, single);
  world->barrier();
  // Iterative on 2 ranks, as the test is about (auto solves this small block directly on both).
  const auto s = test::runDeck(deck, {"Linear solver/type=iterative"}, dirParallel, world);
  ASSERT_EQ(s.at("ranks").get<int>(), 2);
  ASSERT_TRUE(s.at("converged").get<bool>());
  if (rank != 0) return;
  const auto &u = s.at("final_displacement");
  const auto origin = u.at("origin").get<std::vector<double>>(), edge = u.at("bottom edge").get<std::vector<double>>();
  EXPECT_EQ(origin[0], 0.0);
  EXPECT_EQ(origin[1], 0.0);
  EXPECT_EQ(edge[1], 0.0);
  const double p = 1e3, eps = 1e10;
  for (const char *point : {"origin", "bottom edge", "bottom inner", "bottom corner"})
    EXPECT_NEAR(-eps * u.at(point).get<std::vector<double>>()[2], p, 1e-6 * p) << point;
  const auto a = finalField(dirSerial), b = finalField(dirParallel);
  ASSERT_EQ(a.size(), b.size());
  // Every node of the x = 0 and y = 0 faces (the deck's box, generated again for its nodes).
  const mesh::HexMesh box = mesh::generateBox({0, 0, 0}, {1e-3, 1e-3, 1e-3}, {3, 3, 2});
  ASSERT_EQ(b.size(), 3 * box.numNodes());
  int fixed = 0;
  for (std::size_t n = 0; n < box.numNodes(); ++n)
    for (int c = 0; c < 2; ++c)
      if (box.nodes[n][c] == 0.0) {
        EXPECT_EQ(b[3 * n + c], 0.0) << "node " << n << " component " << c;
        ++fixed;
      }
  EXPECT_EQ(fixed, 2 * 4 * 3);
  double scale = 0.0, diff = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    scale = std::max(scale, std::abs(a[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
  }
  EXPECT_LT(diff, 1e-8 * scale) << "max difference " << diff << " of " << scale;
  std::printf("contact patch: max |u_1 - u_2| = %.3e of max |u| = %.3e\n", diff, scale);
}

// The two-block contact patch test (inputs/verification/two_block_patch.xml) with one block on
// each rank (the coordinate bisection cuts at the interface, checked here): the slave block's
// contact points on one rank pair with master faces whose nodes the other rank owns, their forces
// and tangent entries reaching them through the overlap assembly. The field agrees with one rank's
// to 1e-8, and the slave's nodes sink p / eps below the master's top as on one rank.
TEST(MpiConsistency, TwoBlockPatchAgreesWithTheBlocksOnDifferentRanks) {
  auto world = test::worldComm();
  ASSERT_EQ(world->getSize(), 2) << "run this test with mpiexec -np 2";
  const int rank = world->getRank();
  const std::string deck = test::inputPath("verification/two_block_patch.xml");
  const mesh::HexMesh blocks = mesh::readAbaqus(test::inputPath("verification/two_blocks.inp")).mesh;
  const std::vector<int> owner = mesh::partitionElements(blocks, 2);
  ASSERT_EQ(owner.size(), 64u);
  for (std::size_t e = 0; e < 64; ++e) ASSERT_EQ(owner[e], owner[e < 32 ? 0 : 32]) << "element " << e;
  ASSERT_NE(owner[0], owner[32]) << "the blocks on different ranks";
  auto single = world->split(rank, 0);
  const std::vector<std::string> overrides = {"Linear solver/type=iterative", "Linear solver/tolerance=1e-12",
                                              "Nonlinear solver/forcing term=constant"};
  const auto dirSerial = test::scratchDirectory("mpi_serial_pair"), dirParallel = test::scratchDirectory("mpi_parallel_pair");
  if (rank == 0) test::runDeck(deck, overrides, dirSerial, single);
  world->barrier();
  const auto s = test::runDeck(deck, overrides, dirParallel, world);
  ASSERT_EQ(s.at("ranks").get<int>(), 2);
  ASSERT_TRUE(s.at("converged").get<bool>());
  if (rank != 0) return;
  const auto a = finalField(dirSerial), b = finalField(dirParallel);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.size(), 3 * blocks.numNodes());
  double scale = 0.0, diff = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    scale = std::max(scale, std::abs(a[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
  }
  EXPECT_LT(diff, 1e-8 * scale) << "max difference " << diff << " of " << scale;
  const auto &u = s.at("final_displacement");
  const double p = 1e3, eps = 1e10, master = u.at("master a").get<std::vector<double>>()[2];
  for (const char *point : {"slave a", "slave b", "slave edge"})
    EXPECT_NEAR(eps * (master - u.at(point).get<std::vector<double>>()[2]), p, 1e-6 * p) << point;
  std::printf("two-block patch: max |u_1 - u_2| = %.3e of max |u| = %.3e\n", diff, scale);
}

// A dynamic run (the large cantilever of inputs/verification/nonlinear_vibration.xml, half a
// period): displacement, velocity and acceleration fields and the last step's energies the same
// on one rank and on two to 1e-8 relative.
TEST(MpiConsistency, DynamicOneAndTwoRanksAgree) {
  auto world = test::worldComm();
  ASSERT_EQ(world->getSize(), 2) << "run this test with mpiexec -np 2";
  const int rank = world->getRank();
  auto single = world->split(rank, 0);
  const std::vector<std::string> sets{"Time/end time=0.3", "Linear solver/type=iterative", "Linear solver/tolerance=1e-12",
                                      "Nonlinear solver/forcing term=constant", "Nonlinear solver/residual tolerance=1e-10"};
  // Generalized-alpha, and the energy-conserving step's element corrections at the nearly
  // incompressible limit (its elements split between the ranks with their committed states).
  for (const char *name : {"nonlinear_vibration", "nonlinear_vibration_nearly_incompressible"}) {
    const auto deck = test::inputPath(std::string("verification/") + name + ".xml");
    const auto dirSerial = test::scratchDirectory(std::string("mpi_serial_") + name),
               dirParallel = test::scratchDirectory(std::string("mpi_parallel_") + name);
    if (rank == 0) test::runDeck(deck, sets, dirSerial, single);
    world->barrier();
    test::runDeck(deck, sets, dirParallel, world);
    if (rank != 0) continue;
    for (const char *field : {"displacement", "velocity", "acceleration"}) {
      const auto a = test::lastStepField(dirSerial, field), b = test::lastStepField(dirParallel, field);
      ASSERT_EQ(a.size(), b.size());
      double scale = 0.0, diff = 0.0;
      for (std::size_t i = 0; i < a.size(); ++i) {
        scale = std::max(scale, std::abs(a[i]));
        diff = std::max(diff, std::abs(a[i] - b[i]));
      }
      EXPECT_GT(scale, 0.0) << name << " " << field;
      EXPECT_LT(diff, 1e-8 * scale) << name << " " << field << ": max difference " << diff << " of " << scale;
      std::printf("%s %s: max difference %.3e of %.3e\n", name, field, diff, scale);
    }
    const auto e1 = test::readKeyedCsv(dirSerial / "energy.csv"), e2 = test::readKeyedCsv(dirParallel / "energy.csv");
    const auto &last1 = e1.at("all").back().values, &last2 = e2.at("all").back().values;
    EXPECT_NEAR(last2[2], last1[2], 1e-8 * last1[2]) << name; // total energy
  }
}
