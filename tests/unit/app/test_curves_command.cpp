// glossa curves: the three tables over their documented ranges, with the round values of the
// grid exact (lambda_c = 1, rate = 0), and each column the curve it names, to the 17 digits
// written.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "ProcessScratch.hpp"
#include "app/CurvesCommand.hpp"
#include "materials/ContractileCurveSets.hpp"
#include "materials/ParallelElement.hpp"
#include "materials/SeriesElement.hpp"

namespace glossa::app {
namespace {

struct Table {
  std::string header;
  std::vector<std::vector<double>> rows;
};

Table readTable(const std::filesystem::path &file) {
  Table t;
  std::ifstream in(file);
  std::getline(in, t.header);
  for (std::string line; std::getline(in, line);) {
    std::stringstream s(line);
    std::vector<double> row;
    for (std::string cell; std::getline(s, cell, ',');) row.push_back(std::stod(cell));
    t.rows.push_back(row);
  }
  return t;
}

// The tables, written once per process into its own scratch directory (ctest runs each test in
// its own process, two at once: with a shared directory one removed the other's tables while it
// read them), removed when the process ends.
const std::filesystem::path &tables() {
  static const std::filesystem::path written = [] {
    const std::filesystem::path dir = test::processScratch() / "curves";
    EXPECT_EQ(writeCurveTables(dir).size(), 3u);
    return dir;
  }();
  return written;
}

TEST(CurvesCommand, ForceLengthOverItsRangeIsBothCurveSets) {
  const Table t = readTable(tables() / "force_length.csv");
  EXPECT_EQ(t.header, "lambda_c [-],f_cL_physiological [-],f_cL_paper_table_II [-]");
  ASSERT_EQ(t.rows.size(), 381u);
  EXPECT_EQ(t.rows.front()[0], 0.3);
  EXPECT_EQ(t.rows.back()[0], 2.2);
  EXPECT_EQ(t.rows[140][0], 1.0); // 0.3 + 140 * 0.005, exactly
  const auto phys = materials::physiologicalCurves(), paper = materials::paperTableIICurves();
  for (const auto &row : t.rows) {
    EXPECT_EQ(row[1], phys.forceLength->evaluate(row[0]).value) << "lambda_c " << row[0];
    EXPECT_EQ(row[2], paper.forceLength->evaluate(row[0]).value) << "lambda_c " << row[0];
  }
}

TEST(CurvesCommand, ForceVelocityOverItsRangeIsBothCurveSets) {
  const Table t = readTable(tables() / "force_velocity.csv");
  EXPECT_EQ(t.header, "lambda_c_rate [1/s],f_cV_physiological [-],f_cV_paper_table_II [-]");
  ASSERT_EQ(t.rows.size(), 481u);
  EXPECT_EQ(t.rows.front()[0], -12.0);
  EXPECT_EQ(t.rows.back()[0], 12.0);
  EXPECT_EQ(t.rows[240][0], 0.0);
  const auto phys = materials::physiologicalCurves(), paper = materials::paperTableIICurves();
  for (const auto &row : t.rows) {
    EXPECT_EQ(row[1], phys.forceVelocity->evaluate(row[0]).value) << "rate " << row[0];
    EXPECT_EQ(row[2], paper.forceVelocity->evaluate(row[0]).value) << "rate " << row[0];
  }
}

TEST(CurvesCommand, PassiveAndSeriesCurvesAreTensionsOverT0max) {
  const Table t = readTable(tables() / "passive_series.csv");
  EXPECT_EQ(t.header, "lambda [-],f_p [-],f_s [-]");
  ASSERT_EQ(t.rows.size(), 401u);
  EXPECT_EQ(t.rows.front()[0], 0.8);
  EXPECT_EQ(t.rows.back()[0], 1.6);
  const auto parallel = materials::ParallelElement::tableI();
  const auto series = materials::SeriesElement::tableI(parallel.T0max());
  for (const auto &row : t.rows) {
    EXPECT_EQ(row[1], parallel.evaluate(row[0]).T / parallel.T0max()) << "lambda " << row[0];
    EXPECT_EQ(row[2], series.evaluate(row[0], 1.0).T / parallel.T0max()) << "lambda " << row[0];
  }
}

} // namespace
} // namespace glossa::app
