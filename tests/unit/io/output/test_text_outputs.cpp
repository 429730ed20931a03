// traces.csv and summary.json: numbers read back exactly, files are complete after every call,
// the atomic replacement leaves no temporary file behind, and a full disk (a file size limit)
// leaves a CSV file ending at its last complete row and an error naming it.

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "FileSizeLimit.hpp"
#include "ScratchDirectory.hpp"
#include "io/output/AtomicFile.hpp"
#include "io/output/OutputError.hpp"
#include "io/output/SummaryWriter.hpp"
#include "io/output/TraceWriter.hpp"

namespace glossa::io {
namespace {

using testing::ScratchDirectory;

struct TraceRow {
  double time;
  std::string point;
  Eigen::Vector3d u;
};

std::vector<std::string> lines(const std::filesystem::path &path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// Parses the rows after the header; strtod reads the text back to the nearest double.
std::vector<TraceRow> parseTraces(const std::filesystem::path &path) {
  std::vector<TraceRow> rows;
  const auto all = lines(path);
  for (std::size_t i = 1; i < all.size(); ++i) {
    std::vector<std::string> cell;
    std::istringstream row(all[i]);
    for (std::string c; std::getline(row, c, ',');) cell.push_back(c);
    EXPECT_EQ(cell.size(), 8u) << all[i];
    if (cell.size() != 8) continue;
    // Written without a zero-strain configuration: the offset from the imaged position is u.
    for (int c = 0; c < 3; ++c) EXPECT_EQ(cell[5 + c], cell[2 + c]) << all[i];
    auto number = [](const std::string &s) { return std::strtod(s.c_str(), nullptr); };
    rows.push_back({number(cell[0]), cell[1], {number(cell[2]), number(cell[3]), number(cell[4])}});
  }
  return rows;
}

TEST(TraceWriter, RowsRoundTripExactlyAndAreOnDiskAfterEachCall) {
  ScratchDirectory dir;
  const std::filesystem::path file = dir / "nested/traces.csv"; // parent created on demand
  const double tiny = std::numeric_limits<double>::denorm_min(), huge = std::numeric_limits<double>::max();
  const std::vector<std::pair<std::string, Eigen::Vector3d>> first = {
      {"tip", {0.1, 1.0 / 3.0, -2.0 / 7.0}}, {"corner_A", {tiny, -huge, M_PI * 1e-200}}};
  const std::vector<std::pair<std::string, Eigen::Vector3d>> second = {
      {"tip", {1e-17, std::nextafter(1.0, 2.0), -0.0}}, {"corner_A", {123456789.123456789, 0.0, 5e-324}}};

  TraceWriter traces(file);
  EXPECT_EQ(lines(file), std::vector<std::string>{"time [s],point,ux [m],uy [m],uz [m],dx [m],dy [m],dz [m]"});
  traces.append(0.1, first);
  EXPECT_EQ(parseTraces(file).size(), 2u); // flushed: readable while the writer is alive
  traces.append(2.0 / 3.0, second);

  const auto rows = parseTraces(file);
  ASSERT_EQ(rows.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const auto &expected = i < 2 ? first[i] : second[i - 2];
    EXPECT_EQ(rows[i].time, i < 2 ? 0.1 : 2.0 / 3.0);
    EXPECT_EQ(rows[i].point, expected.first);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(rows[i].u[c], expected.second[c]) << "row " << i << " component " << c;
  }
  EXPECT_TRUE(std::signbit(rows[2].u.z())); // even -0.0 survives
}

TEST(TraceWriter, RefusesPointNamesCsvCannotCarry) {
  ScratchDirectory dir;
  TraceWriter traces(dir / "traces.csv");
  using Displacements = std::vector<std::pair<std::string, Eigen::Vector3d>>; // not TraceWriter::Point
  EXPECT_THROW(traces.append(0.0, Displacements{{"a,b", Eigen::Vector3d::Zero()}}), std::invalid_argument);
  EXPECT_THROW(traces.append(0.0, Displacements{{"ok", Eigen::Vector3d::Zero()}, {"", Eigen::Vector3d::Zero()}}),
               std::invalid_argument);
  EXPECT_EQ(lines(dir / "traces.csv").size(), 1u); // nothing of a refused call is written
}

TEST(SummaryWriter, WritesParsableJsonAtomically) {
  ScratchDirectory dir;
  const std::filesystem::path file = dir / "summary.json";
  SummaryWriter summary(file);
  summary.root()["converged"] = false;
  summary.root()["ranks"] = 4;
  summary.root()["dofs"] = 123456;
  summary.root()["elements"] = 2;
  summary.appendStep({{"time", 0.5}, {"newton", 3}});
  EXPECT_FALSE(std::filesystem::exists(file)); // nothing before write()
  summary.write();

  auto read = [&] {
    std::ifstream in(file);
    return nlohmann::json::parse(in);
  };
  nlohmann::json back = read();
  EXPECT_EQ(back, summary.root());
  EXPECT_FALSE(std::filesystem::exists(temporaryPathFor(file)));

  summary.root()["converged"] = true;
  summary.root()["wall_seconds"] = 1.0 / 3.0;
  summary.root()["final_displacement"] = {{"tip", {0.1, 0.2, 0.3}}};
  summary.appendStep({{"time", 1.0}, {"newton", 4}});
  summary.write();
  back = read();
  EXPECT_EQ(back, summary.root());
  EXPECT_EQ(back["steps"].size(), 2u);
  EXPECT_EQ(back["wall_seconds"].get<double>(), 1.0 / 3.0);
  EXPECT_FALSE(std::filesystem::exists(temporaryPathFor(file)));
}

TEST(SummaryWriter, NonFiniteNumbersBecomeNull) {
  ScratchDirectory dir;
  SummaryWriter summary(dir / "summary.json");
  summary.root()["residual"] = std::nan("");
  summary.write();
  std::ifstream in(dir / "summary.json");
  EXPECT_TRUE(nlohmann::json::parse(in)["residual"].is_null());
}

TEST(AtomicFile, ReplacesContentsAndLeavesNoTemporary) {
  ScratchDirectory dir;
  const auto file = dir / "index.txt";
  replaceFileAtomically(file, "old\n");
  replaceFileAtomically(file, "new\n");
  EXPECT_EQ(lines(file), std::vector<std::string>{"new"});
  EXPECT_FALSE(std::filesystem::exists(temporaryPathFor(file)));
}

TEST(AtomicFile, FailureLeavesTargetUntouched) {
  ScratchDirectory dir;
  const auto file = dir / "index.txt";
  replaceFileAtomically(file, "kept\n");
  // A directory where the temporary file should go makes open(2) fail.
  std::filesystem::create_directory(temporaryPathFor(file));
  EXPECT_THROW(replaceFileAtomically(file, "lost\n"), std::runtime_error);
  EXPECT_EQ(lines(file), std::vector<std::string>{"kept"});
  EXPECT_THROW(replaceFileAtomically(dir / "missing/index.txt", "x"), std::runtime_error);
}

// A full disk, as RLIMIT_FSIZE makes one (SIGXFSZ ignored: the write fails with EFBIG): a child
// appends rows of 100 points until a write fails part-way through a row. The file must end at the
// last complete row (a reader parses every row), and the error must name the file and the reason.
TEST(TraceWriter, AFullDiskLeavesCompleteRowsAndNamesTheFile) {
  ScratchDirectory dir;
  const auto file = dir / "traces.csv";
  std::vector<std::pair<std::string, Eigen::Vector3d>> points;
  for (int p = 0; p < 100; ++p) points.emplace_back("p" + std::to_string(p), Eigen::Vector3d(p / 3.0, -p / 7.0, 1.0 / (p + 1)));
  constexpr std::uintmax_t kLimit = 50000; // not a whole number of calls' rows
  const std::string ended = testing::underFileSizeLimit(kLimit, [&] {
    TraceWriter writer(file);
    try {
      for (int step = 0; step < 1000; ++step) writer.append(0.1 * step, points);
    } catch (const OutputError &e) {
      const std::string what = e.what();
      return what.find(file.string()) != std::string::npos && what.find("File too large") != std::string::npos ? 0 : 12;
    }
    return 11;
  });
  ASSERT_EQ(ended, "exit 0") << "100: no limit; 11: nothing failed; 12: another message";
  const auto rows = parseTraces(file); // every row has its 8 fields
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.size() % points.size(), 0u) << "a call's rows are written whole or not at all";
  EXPECT_LE(std::filesystem::file_size(file), kLimit);
  std::ifstream in(file, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text.back(), '\n');
}

} // namespace
} // namespace glossa::io
