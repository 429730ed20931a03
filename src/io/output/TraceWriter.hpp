#pragma once
// traces.csv: the displacement of named points over time, "time,point,ux,uy,uz", one row per
// point per call (a KeyedCsvWriter: round-trip numbers, each call's rows on disk when it returns).

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "io/output/KeyedCsvWriter.hpp"

namespace glossa::io {

class TraceWriter {
public:
  // Creates (or empties) `file` and writes the header; creates the parent directory if missing.
  // Throws std::runtime_error if the file cannot be written.
  explicit TraceWriter(const std::filesystem::path &file) : csv_(file, "point", {"ux", "uy", "uz"}) {}

  // Throws std::invalid_argument (before writing anything) for a point name that CSV cannot
  // carry unquoted: empty, or containing ',', '"', '\n' or '\r'; std::runtime_error if writing
  // fails (e.g. a full disk).
  void append(double time, const std::vector<std::pair<std::string, Eigen::Vector3d>> &pointDisplacements) {
    std::vector<std::pair<std::string, std::vector<double>>> rows;
    for (const auto &[name, u] : pointDisplacements) rows.push_back({name, {u.x(), u.y(), u.z()}});
    csv_.append(time, rows);
  }

private:
  KeyedCsvWriter csv_;
};

} // namespace glossa::io
