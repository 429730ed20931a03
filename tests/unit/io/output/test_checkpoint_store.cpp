// Checkpoints (glossa run --restart): every double comes back bit-identical, `latest` names only
// a checkpoint whose parts were all written, an unpublished (killed) checkpoint is never read,
// and publishing removes the older ones. A CSV resumed at a checkpoint's length loses the rows
// written after it, a row cut short by a kill too.

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ScratchDirectory.hpp"
#include "io/output/CheckpointStore.hpp"
#include "io/output/KeyedCsvWriter.hpp"
#include "io/output/OutputError.hpp"

namespace glossa::io {
namespace {

using testing::ScratchDirectory;

std::string readText(const std::filesystem::path &path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(CheckpointStore, PartsReadBackBitIdentical) {
  ScratchDirectory dir;
  const CheckpointStore store(dir.path());
  EXPECT_FALSE(store.latestStep().has_value());
  const std::vector<double> values = {0.1, 1.0 / 3.0, -2.5e-300, 1e300, std::nextafter(1.0, 2.0), 0.0, -0.0,
                                      std::numeric_limits<double>::denorm_min()};
  for (int rank = 0; rank < 2; ++rank) store.writePart(7, rank, {{"u", values}, {"rank", rank}, {"name", "tongue"}});
  store.publish(7);
  ASSERT_EQ(store.latestStep(), 7);
  for (int rank = 0; rank < 2; ++rank) {
    const nlohmann::json part = store.readPart(7, rank);
    const auto u = part.at("u").get<std::vector<double>>();
    ASSERT_EQ(u.size(), values.size());
    for (std::size_t i = 0; i < u.size(); ++i) {
      EXPECT_EQ(std::memcmp(&u[i], &values[i], sizeof(double)), 0) << i; // -0.0 too
    }
    EXPECT_EQ(part.at("rank").get<int>(), rank);
  }
}

TEST(CheckpointStore, AnUnpublishedCheckpointIsNeverReadAndPublishingRemovesTheOlder) {
  ScratchDirectory dir;
  const CheckpointStore store(dir.path());
  store.writePart(5, 0, {{"step", 5}});
  store.publish(5);
  // Killed after rank 0 wrote its part of step 10, before the publication.
  store.writePart(10, 0, {{"step", 10}});
  EXPECT_EQ(store.latestStep(), 5);
  EXPECT_EQ(store.readPart(5, 0).at("step").get<int>(), 5);
  store.publish(10);
  EXPECT_EQ(store.latestStep(), 10);
  EXPECT_FALSE(std::filesystem::exists(dir / "checkpoint/step_000005"));
  EXPECT_TRUE(std::filesystem::exists(dir / "checkpoint/step_000010/rank_0000.cbor"));
}

TEST(CheckpointStore, AMissingOrDamagedPartIsAnOutputErrorNamingTheFile) {
  ScratchDirectory dir;
  const CheckpointStore store(dir.path());
  store.writePart(3, 0, {{"u", {1.0, 2.0}}});
  store.publish(3);
  EXPECT_THROW(store.readPart(3, 1), OutputError);
  std::ofstream(dir / "checkpoint/step_000003/rank_0000.cbor", std::ios::binary | std::ios::trunc) << "\xff\x01";
  try {
    store.readPart(3, 0);
    FAIL() << "a damaged part was read";
  } catch (const OutputError &e) {
    EXPECT_NE(std::string(e.what()).find("rank_0000.cbor"), std::string::npos) << e.what();
  }
}

TEST(KeyedCsvWriter, ResumedAtACheckpointsLengthLosesTheLaterRowsAndCarriesOn) {
  ScratchDirectory dir;
  const std::filesystem::path file = dir / "traces.csv";
  std::uintmax_t atCheckpoint = 0;
  std::string expected;
  {
    KeyedCsvWriter csv(file, "point", {"ux [m]"});
    csv.append(0.1, {{"P", {1.0}}});
    atCheckpoint = csv.bytes();
    expected = readText(file);
    EXPECT_EQ(atCheckpoint, expected.size());
    csv.append(0.2, {{"P", {2.0}}});
  }
  std::ofstream(file, std::ios::app) << "0.3,P,3.00"; // a row a kill cut short
  {
    KeyedCsvWriter csv(file, "point", {"ux [m]"}, atCheckpoint);
    EXPECT_EQ(readText(file), expected);
    csv.append(0.2, {{"P", {2.5}}});
  }
  EXPECT_EQ(readText(file), expected + "0.20000000000000001,P,2.5\n");
}

TEST(KeyedCsvWriter, ResumingAShorterFileIsAnOutputError) {
  ScratchDirectory dir;
  { KeyedCsvWriter csv(dir / "a.csv", "point", {"ux [m]"}); }
  EXPECT_THROW(KeyedCsvWriter(dir / "a.csv", "point", {"ux [m]"}, 10000), OutputError);
  EXPECT_THROW(KeyedCsvWriter(dir / "missing.csv", "point", {"ux [m]"}, 0), OutputError);
}

} // namespace
} // namespace glossa::io
