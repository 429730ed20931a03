#pragma once
// traces.csv: the displacement of named points over time, "time [s],point,ux [m],uy [m],uz [m],
// dx [m],dy [m],dz [m]", one row per point per call (a KeyedCsvWriter: round-trip numbers, each
// call's rows on disk when it returns). u is the displacement from the reference configuration; d = x - X_img the offset of
// the current position from the point's imaged position, which differs from u only when a
// zero-strain configuration replaced the imaged one (§8.1): it is the controlled runs' goal, so
// passive and controlled runs compare directly whatever their reference configuration.

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
  // `resumeAt`: a restart's (KeyedCsvWriter).
  explicit TraceWriter(const std::filesystem::path &file, std::optional<std::uintmax_t> resumeAt = std::nullopt)
      : csv_(file, "point", {"ux [m]", "uy [m]", "uz [m]", "dx [m]", "dy [m]", "dz [m]"}, resumeAt) {}
  std::uintmax_t bytes() const { return csv_.bytes(); }

  struct Point {
    std::string name;
    Eigen::Vector3d displacement;     // u
    Eigen::Vector3d fromImaged;       // d = X + u - X_img
  };

  // Throws std::invalid_argument (before writing anything) for a point name that CSV cannot
  // carry unquoted: empty, or containing ',', '"', '\n' or '\r'; std::runtime_error if writing
  // fails (e.g. a full disk).
  void appendPoints(double time, const std::vector<Point> &points) {
    std::vector<std::pair<std::string, std::vector<double>>> rows;
    for (const auto &p : points)
      rows.push_back({p.name, {p.displacement.x(), p.displacement.y(), p.displacement.z(), p.fromImaged.x(),
                               p.fromImaged.y(), p.fromImaged.z()}});
    csv_.append(time, rows);
  }
  // The reference configuration is the imaged one: d = u.
  void append(double time, const std::vector<std::pair<std::string, Eigen::Vector3d>> &pointDisplacements) {
    std::vector<Point> points;
    for (const auto &[name, u] : pointDisplacements) points.push_back({name, u, u});
    appendPoints(time, points);
  }

private:
  KeyedCsvWriter csv_;
};

} // namespace glossa::io
