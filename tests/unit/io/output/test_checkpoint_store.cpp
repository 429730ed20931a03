// Checkpoints (glossa run --restart): every double comes back bit-identical, `latest` names only
// a checkpoint whose parts were all written, an unpublished (killed) checkpoint is never read,
// and publishing removes the older ones. A part proves itself: every single-bit flip and every
// truncation of a part is refused, as are another rank's or step's part, a file that is not a
// checkpoint and a `latest` that does not name one, each a CheckpointError naming the file. A CSV resumed at a checkpoint's length loses the rows
// written after it, a row cut short by a kill too.

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ScratchDirectory.hpp"
#include "io/output/CheckpointError.hpp"
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

// The message of the CheckpointError `f` throws, "" if none.
template <class F> std::string refusal(F &&f) {
  try {
    f();
  } catch (const CheckpointError &e) {
    return e.what();
  }
  return "";
}

TEST(CheckpointStore, AMissingOrDamagedPartIsACheckpointErrorNamingTheFile) {
  ScratchDirectory dir;
  const CheckpointStore store(dir.path());
  store.writePart(3, 0, {{"u", {1.0, 2.0}}});
  store.publish(3);
  EXPECT_NE(refusal([&] { store.readPart(3, 1); }).find("rank_0001.cbor is missing"), std::string::npos);
  std::ofstream(dir / "checkpoint/step_000003/rank_0000.cbor", std::ios::binary | std::ios::trunc) << "\xff\x01";
  const std::string why = refusal([&] { store.readPart(3, 0); });
  EXPECT_NE(why.find("rank_0000.cbor: not a Glossa checkpoint part (2 bytes"), std::string::npos) << why;
}

TEST(CheckpointStore, EveryBitFlipAndEveryTruncationOfAPartIsRefused) {
  ScratchDirectory dir;
  const CheckpointStore store(dir.path());
  store.writePart(4, 0, {{"u", {0.1, 1.0 / 3.0}}, {"time", 0.5}, {"deck", "Time/end time = 1"}});
  const std::filesystem::path file = store.partPath(4, 0);
  const std::string bytes = readText(file);
  ASSERT_EQ(bytes.size(), CheckpointStore::kHeaderBytes + nlohmann::json::to_cbor(store.readPart(4, 0)).size() +
                              CheckpointStore::kTrailerBytes);
  auto refused = [&](const std::string &damaged) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << damaged;
    return refusal([&] { store.readPart(4, 0); });
  };
  for (std::size_t i = 0; i < bytes.size(); ++i)
    for (int bit = 0; bit < 8; ++bit) {
      std::string flipped = bytes;
      flipped[i] = static_cast<char>(flipped[i] ^ (1 << bit));
      const std::string why = refused(flipped);
      ASSERT_NE(why.find(file.string()), std::string::npos) << "byte " << i << " bit " << bit << ": '" << why << "'";
    }
  for (std::size_t length = 0; length < bytes.size(); ++length)
    ASSERT_NE(refused(bytes.substr(0, length)).find(file.string()), std::string::npos) << length;
  EXPECT_NE(refused(bytes + "x").find("the header announces"), std::string::npos);
  EXPECT_NE(refused(bytes.substr(0, bytes.size() - 1)).find("(cut short or run on)"), std::string::npos);
  std::string payload = bytes;
  payload[40] = static_cast<char>(payload[40] ^ 1);
  EXPECT_NE(refused(payload).find("the file is damaged: its CRC-32 is"), std::string::npos);
  EXPECT_EQ(refused(bytes), "");
}

TEST(CheckpointStore, AnotherRanksOrStepsPartIsRefused) {
  ScratchDirectory dir;
  const CheckpointStore store(dir.path());
  store.writePart(6, 1, {{"u", {1.0}}});
  std::filesystem::create_directories(dir / "checkpoint/step_000007");
  std::filesystem::copy_file(store.partPath(6, 1), store.partPath(6, 0));
  std::filesystem::copy_file(store.partPath(6, 1), store.partPath(7, 1));
  EXPECT_NE(refusal([&] { store.readPart(6, 0); }).find("it is rank 1's part of step 6, not rank 0's of step 6"),
            std::string::npos);
  EXPECT_NE(refusal([&] { store.readPart(7, 1); }).find("it is rank 1's part of step 6, not rank 1's of step 7"),
            std::string::npos);
}

TEST(CheckpointStore, ALatestThatDoesNotNameACheckpointIsRefused) {
  ScratchDirectory dir;
  const CheckpointStore store(dir.path());
  store.writePart(4, 0, {{"u", {1.0}}});
  store.publish(4);
  EXPECT_EQ(readText(dir / "checkpoint/latest"), "step_000004\n");
  for (const std::string text : {"step_00000t\n", "step_000004", "step_000004\x0b", "", "step_-00004\n", "latest\n"}) {
    std::ofstream(dir / "checkpoint/latest", std::ios::binary | std::ios::trunc) << text;
    const std::string why = refusal([&] { store.latestStep(); });
    EXPECT_NE(why.find("checkpoint/latest holds"), std::string::npos) << "'" << text << "': " << why;
  }
  std::filesystem::remove(dir / "checkpoint/latest");
  EXPECT_FALSE(store.latestStep().has_value());
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
