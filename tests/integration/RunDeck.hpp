#pragma once
// Runs a deck from inputs/ the way `glossa run` does, for the integration tests.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/DeckSchema.hpp"
#include "io/deck/Deck.hpp"
#include "solvers/run/RunSimulation.hpp"
#include "WorldComm.hpp"

namespace glossa::test {

inline std::string inputPath(const std::string &relative) { return std::string(GLOSSA_SOURCE_DIR) + "/inputs/" + relative; }

inline std::filesystem::path scratchDirectory(const std::string &name) {
  auto dir = std::filesystem::path(GLOSSA_BINARY_DIR) / "test-output" / name;
  return dir;
}

inline nlohmann::json runDeck(const std::string &deckFile, const std::vector<std::string> &overrides,
                              const std::filesystem::path &output,
                              Teuchos::RCP<const Teuchos::Comm<int>> comm = worldComm()) {
  const auto schema = app::deckSchema();
  auto deck = io::Deck::fromFile(deckFile);
  for (const auto &o : overrides) deck.applyOverride(o, schema);
  deck.validate(schema);
  return solvers::runSimulation(deck, solvers::parseRunConfiguration(deck), comm, {output, true});
}

struct TraceRow {
  double time;
  std::string point;
  double u[3];
  double d[3]; // from the imaged position (u where the file has no dx, dy, dz)
};

inline std::vector<TraceRow> readTraces(const std::filesystem::path &file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line); // header
  std::vector<TraceRow> rows;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    TraceRow r{};
    std::string cell;
    std::getline(s, cell, ',');
    r.time = std::stod(cell);
    std::getline(s, r.point, ',');
    for (double &v : r.u) {
      std::getline(s, cell, ',');
      v = std::stod(cell);
    }
    for (int c = 0; c < 3; ++c) r.d[c] = std::getline(s, cell, ',') ? std::stod(cell) : r.u[c];
    rows.push_back(r);
  }
  return rows;
}

// A KeyedCsvWriter file (volumes.csv, resultants.csv, reactions.csv): per key, its rows
// (time, values) in file order.
struct KeyedRow {
  double time;
  std::vector<double> values;
};
inline std::map<std::string, std::vector<KeyedRow>> readKeyedCsv(const std::filesystem::path &file) {
  std::ifstream in(file);
  EXPECT_TRUE(in.good()) << "cannot read " << file;
  std::string line;
  std::getline(in, line); // header
  std::map<std::string, std::vector<KeyedRow>> rows;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string cell, key;
    std::getline(s, cell, ',');
    KeyedRow r{std::stod(cell), {}};
    std::getline(s, key, ',');
    while (std::getline(s, cell, ',')) r.values.push_back(std::stod(cell));
    rows[key].push_back(r);
  }
  return rows;
}

// The largest displacement magnitude of `point` over a stored trace file.
inline double peakDisplacement(const std::filesystem::path &file, const std::string &point) {
  double peak = 0.0;
  for (const auto &r : readTraces(file))
    if (r.point == point) peak = std::max(peak, std::sqrt(r.u[0] * r.u[0] + r.u[1] * r.u[1] + r.u[2] * r.u[2]));
  return peak;
}

// y-displacement of `point` at each written time.
inline std::map<double, double> traceOf(const std::vector<TraceRow> &rows, const std::string &point, int component) {
  std::map<double, double> out;
  for (const auto &r : rows)
    if (r.point == point) out[r.time] = r.u[component];
  return out;
}

// Quadratic Newton: e_{k+1} <= 10 e_k^2 for e = |f| / |f_0|, f_0 the first residual of the step
// (the scale of its load increment), in every Newton solve of the step (Uzawa's included), once
// e < 1e-2 and while e_{k+1} is above `floor` (round-off). Returns how many pairs were checked.
inline int expectQuadraticNewton(const nlohmann::json &summary, double floor = 1e-10) {
  int checked = 0;
  for (const auto &step : summary.at("steps")) {
    const double scale = step.at("newton_solves").front().at("residual_norms").at(0).get<double>();
    for (const auto &solve : step.at("newton_solves")) {
      const auto r = solve.at("residual_norms").get<std::vector<double>>();
      for (std::size_t k = 0; k + 1 < r.size(); ++k) {
        const double e = r[k] / scale, next = r[k + 1] / scale;
        if (e > 1e-2 || next < floor) continue;
        EXPECT_LE(next, 10.0 * e * e) << "step at t = " << step.at("time") << ", iteration " << k;
        ++checked;
      }
    }
  }
  return checked;
}

} // namespace glossa::test
