// Checkpoints without a run: a part written is read back as it was, once published; a restart
// is refused, naming why, when there is no checkpoint, when the deck differs (the first
// parameter that does), or when the ranks or control groups do; a damaged part or an edited
// value is refused on every rank alike (an io::CheckpointError, so exit 2), naming the file.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <cmath>
#include <fstream>
#include <limits>

#include "DeckOnFile.hpp"
#include "SharedScratch.hpp"
#include "io/output/OutputError.hpp"
#include "solvers/run/CheckpointContents.hpp"
#include "solvers/run/RunCheckpoint.hpp"

using namespace glossa;
using namespace glossa::solvers;

namespace {
const std::string kListing = "Time/end time = 1\nTime/step size = 0.25\n";

// A rank's part as the Simulation writes it after step `step` at t = 0.5 s: its state (three
// displacements, one element, no muscles), and rank 0's run part.
nlohmann::json part(int ranks, int step = 1, double t = 0.5) {
  nlohmann::json p = {{"u", {0.0, 1.5, -2.25}},
                      {"lambda", nlohmann::json::array({3.0})},
                      {"muscle", toJson(model::MuscleHistory::Snapshot{{}, {}, {}, {}, t, 0.25})}};
  if (Tpetra::getDefaultComm()->getRank() == 0)
    p["run"] = {{"deck", kListing},       {"ranks", ranks},
                {"control_groups", 1},    {"step", step},
                {"time", t},              {"previous_dt", 0.25},
                {"step_size", {0.25, 0}}, {"penalty_ratios", nlohmann::json::array({30.0})},
                {"softening_said", false}, {"outputs", toJson(OutputMark{})},
                {"summary", nlohmann::json::object()}};
  return p;
}

// This run's state on every rank: the part's sizes, end time 1 s, steps of 0.25 s.
CheckpointShape shape() {
  CheckpointShape s;
  s.endTime = 1.0;
  s.nominalStep = 0.25;
  s.displacements = 3;
  s.elements = 1;
  s.tissues = 1;
  return s;
}

} // namespace

TEST(RunCheckpoint, APartWrittenIsReadBackAsItWas) {
  glossa::testing::SharedScratch dir;
  const auto comm = Tpetra::getDefaultComm();
  RunCheckpoint checkpoints(dir.path(), comm, 5);
  EXPECT_TRUE(checkpoints.due(10));
  EXPECT_FALSE(checkpoints.due(7));
  checkpoints.write(10, part(comm->getSize(), 10));
  const auto restart = RunCheckpoint::read(dir.path(), *comm, kListing, 1, shape());
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
  const std::string why = test::deckErrorOf([&] { RunCheckpoint::read(dir.path(), *Tpetra::getDefaultComm(), kListing, 1, shape()); });
  EXPECT_NE(why.find("no checkpoint there"), std::string::npos) << why;
}

TEST(RunCheckpoint, ARestartWithAnotherDeckNamesTheFirstDifference) {
  glossa::testing::SharedScratch dir;
  const auto comm = Tpetra::getDefaultComm();
  RunCheckpoint(dir.path(), comm, 1).write(1, part(comm->getSize()));
  const std::string why = test::deckErrorOf([&] {
    RunCheckpoint::read(dir.path(), *comm, "Time/end time = 1\nTime/step size = 0.5\n", 1, shape());
  });
  EXPECT_NE(why.find("the run's Time/step size = 0.25, now Time/step size = 0.5"), std::string::npos) << why;
}

TEST(RunCheckpoint, ARestartOnOtherRanksOrGroupsIsRefused) {
  glossa::testing::SharedScratch dir;
  const auto comm = Tpetra::getDefaultComm();
  RunCheckpoint(dir.path(), comm, 1).write(1, part(comm->getSize() + 1));
  EXPECT_NE(test::deckErrorOf([&] { RunCheckpoint::read(dir.path(), *comm, kListing, 1, shape()); }).find("restart it on as many"),
            std::string::npos);
  glossa::testing::SharedScratch other;
  RunCheckpoint(other.path(), comm, 1).write(1, part(comm->getSize()));
  EXPECT_NE(test::deckErrorOf([&] { RunCheckpoint::read(other.path(), *comm, kListing, 2, shape()); }).find("control group(s)"),
            std::string::npos);
}

TEST(RunCheckpoint, ADamagedPartIsRefusedOnEveryRankNamingIt) {
  glossa::testing::SharedScratch dir;
  const auto comm = Tpetra::getDefaultComm();
  RunCheckpoint(dir.path(), comm, 1).write(1, part(comm->getSize()));
  // One bit of the last rank's part flipped (on 2 ranks, a part rank 0 never reads).
  const std::string last = "rank_000" + std::to_string(comm->getSize() - 1) + ".cbor";
  if (comm->getRank() == 0) {
    std::fstream f(dir.path() / "checkpoint/step_000001" / last, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(40);
    const char byte = static_cast<char>(f.get() ^ 0x10);
    f.seekp(40);
    f.put(byte);
  }
  comm->barrier();
  const std::string why = test::deckErrorOf([&] { RunCheckpoint::read(dir.path(), *comm, kListing, 1, shape()); });
  EXPECT_NE(why.find("checkpoint/step_000001/" + last + ": the file is damaged: its CRC-32 is"), std::string::npos) << why;
  EXPECT_NE(why.find("it cannot be trusted"), std::string::npos) << why;
}

// The last rank cannot write its part (a directory stands where it goes): every rank throws that
// rank's own words, the file and why. Before, rank 0 reported "another rank could not write its
// checkpoint part" and the job ended before the failing rank's message reached stderr.
TEST(RunCheckpoint, APartThatCannotBeWrittenIsNamedOnEveryRank) {
  glossa::testing::SharedScratch dir;
  const auto comm = Tpetra::getDefaultComm();
  const std::string last = "rank_000" + std::to_string(comm->getSize() - 1) + ".cbor";
  if (comm->getRank() == 0)
    std::filesystem::create_directories(dir.path() / "checkpoint/step_000001" / last / "x");
  comm->barrier();
  RunCheckpoint checkpoints(dir.path(), comm, 1);
  try {
    checkpoints.write(1, part(comm->getSize()));
    ADD_FAILURE() << "the write did not fail";
  } catch (const io::OutputError &e) {
    const std::string why = e.what();
    EXPECT_NE(why.find("cannot "), std::string::npos) << why;
    EXPECT_NE(why.find("checkpoint/step_000001/" + last), std::string::npos) << why;
  }
}

TEST(RunCheckpoint, AnEditedTimeIsRefusedNamingTheFileAndTheValue) {
  const auto comm = Tpetra::getDefaultComm();
  for (const double t : {std::numeric_limits<double>::quiet_NaN(), 1e300}) {
    glossa::testing::SharedScratch dir;
    RunCheckpoint(dir.path(), comm, 1).write(1, part(comm->getSize(), 1, t));
    const std::string why = test::deckErrorOf([&] { RunCheckpoint::read(dir.path(), *comm, kListing, 1, shape()); });
    EXPECT_NE(why.find("checkpoint/step_000001/rank_0000.cbor: time = " + std::string(std::isnan(t) ? "nan" : "1e+300") +
                       "; it must be finite and in [0, 1] (Time/end time)"),
              std::string::npos)
        << why;
  }
}

TEST(RunCheckpoint, APartOfAnotherMeshIsRefusedOnEveryRank) {
  glossa::testing::SharedScratch dir;
  const auto comm = Tpetra::getDefaultComm();
  RunCheckpoint(dir.path(), comm, 1).write(1, part(comm->getSize()));
  CheckpointShape bigger = shape();
  bigger.displacements = 6;
  const std::string why = test::deckErrorOf([&] { RunCheckpoint::read(dir.path(), *comm, kListing, 1, bigger); });
  EXPECT_NE(why.find("rank_0000.cbor: u (displacement) has 3 values, this run has 6 here"), std::string::npos) << why;
}
