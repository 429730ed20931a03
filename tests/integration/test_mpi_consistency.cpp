// Run under mpiexec -np 2: the same deck on one rank (a split communicator) and on both ranks
// gives the same displacement field to 1e-8 relative, for the penalty and the augmented-
// Lagrangian paths.
#include <cmath>

#include <gtest/gtest.h>

#include "RunDeck.hpp"
#include "io/deck/Deck.hpp"

using namespace glossa;

namespace {
// The final displacement of every named point (the block's origin and top-face centre).
std::vector<double> finalField(const std::filesystem::path &dir) {
  std::ifstream in(dir / "summary.json");
  const auto s = nlohmann::json::parse(in);
  std::vector<double> out;
  for (const auto &[name, u] : s.at("final_displacement").items())
    for (double v : u.get<std::vector<double>>()) out.push_back(v);
  return out;
}

void expectSameOnOneAndTwoRanks(const std::vector<std::string> &overrides, const std::string &tag) {
  auto world = Tpetra::getDefaultComm();
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
  double scale = 0.0, diff = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    scale = std::max(scale, std::abs(a[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
  }
  EXPECT_LT(diff, 1e-8 * scale);
}
} // namespace

TEST(MpiConsistency, PenaltyOneAndTwoRanksAgree) {
  expectSameOnOneAndTwoRanks({"Mesh/Box/cells=6,6,6", "Linear solver/tolerance=1e-10", "Nonlinear solver/forcing term=constant"},
                             "penalty");
}

TEST(MpiConsistency, AugmentedLagrangianOneAndTwoRanksAgree) {
  expectSameOnOneAndTwoRanks({"Mesh/Box/cells=6,6,6", "Linear solver/tolerance=1e-10",
                              "Nonlinear solver/forcing term=constant", "Incompressibility/method=augmented Lagrangian"},
                             "al");
}
