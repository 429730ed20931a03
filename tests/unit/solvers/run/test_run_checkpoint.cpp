// Checkpoints without a run: a part written is read back as it was, once published; a restart
// is refused, naming why, when there is no checkpoint, when the deck differs (the first
// parameter that does), or when the ranks or control groups do.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include "DeckOnFile.hpp"
#include "SharedScratch.hpp"
#include "solvers/run/CheckpointContents.hpp"
#include "solvers/run/RunCheckpoint.hpp"

using namespace glossa;
using namespace glossa::solvers;

namespace {
const std::string kListing = "Time/end time = 1\nTime/step size = 0.25\n";

// A rank's part as the Simulation writes it: its state, and rank 0's run part.
nlohmann::json part(int ranks) {
  nlohmann::json p = {{"u", {0.0, 1.5, -2.25}}, {"lambda", {3.0}}};
  if (Tpetra::getDefaultComm()->getRank() == 0)
    p["run"] = {{"deck", kListing}, {"ranks", ranks}, {"control_groups", 1}, {"outputs", toJson(OutputMark{})}};
  return p;
}

} // namespace

TEST(RunCheckpoint, APartWrittenIsReadBackAsItWas) {
  glossa::testing::SharedScratch dir;
  const auto comm = Tpetra::getDefaultComm();
  RunCheckpoint checkpoints(dir.path(), comm, 5);
  EXPECT_TRUE(checkpoints.due(10));
  EXPECT_FALSE(checkpoints.due(7));
  checkpoints.write(10, part(comm->getSize()));
  const auto restart = RunCheckpoint::read(dir.path(), *comm, kListing, 1);
  EXPECT_EQ(restart->step, 10);
  EXPECT_EQ(restart->part.at("u"), nlohmann::json({0.0, 1.5, -2.25}));
  EXPECT_EQ(restart->run.at("deck"), kListing);
}

TEST(RunCheckpoint, NeverWhenEveryIsZero) {
  glossa::testing::SharedScratch dir;
  RunCheckpoint checkpoints(dir.path(), Tpetra::getDefaultComm(), 0);
  EXPECT_FALSE(checkpoints.enabled());
  EXPECT_FALSE(checkpoints.due(0));
}

TEST(RunCheckpoint, ARestartWithoutACheckpointIsRefused) {
  glossa::testing::SharedScratch dir;
  const std::string why = test::deckErrorOf([&] { RunCheckpoint::read(dir.path(), *Tpetra::getDefaultComm(), kListing, 1); });
  EXPECT_NE(why.find("no checkpoint there"), std::string::npos) << why;
}

TEST(RunCheckpoint, ARestartWithAnotherDeckNamesTheFirstDifference) {
  glossa::testing::SharedScratch dir;
  const auto comm = Tpetra::getDefaultComm();
  RunCheckpoint(dir.path(), comm, 1).write(1, part(comm->getSize()));
  const std::string why = test::deckErrorOf([&] {
    RunCheckpoint::read(dir.path(), *comm, "Time/end time = 1\nTime/step size = 0.5\n", 1);
  });
  EXPECT_NE(why.find("the run's Time/step size = 0.25, now Time/step size = 0.5"), std::string::npos) << why;
}

TEST(RunCheckpoint, ARestartOnOtherRanksOrGroupsIsRefused) {
  glossa::testing::SharedScratch dir;
  const auto comm = Tpetra::getDefaultComm();
  RunCheckpoint(dir.path(), comm, 1).write(1, part(comm->getSize() + 1));
  EXPECT_NE(test::deckErrorOf([&] { RunCheckpoint::read(dir.path(), *comm, kListing, 1); }).find("restart it on as many"),
            std::string::npos);
  glossa::testing::SharedScratch other;
  RunCheckpoint(other.path(), comm, 1).write(1, part(comm->getSize()));
  EXPECT_NE(test::deckErrorOf([&] { RunCheckpoint::read(other.path(), *comm, kListing, 2); }).find("control group(s)"),
            std::string::npos);
}
