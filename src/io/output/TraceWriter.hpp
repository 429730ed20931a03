#pragma once
// traces.csv: the displacement of named points over time, one row per point per call,
// "time,point,ux,uy,uz", numbers with 17 significant digits (they read back bit-exactly, which
// the regression suite relies on). Rank 0 writes.
//
// Each call's rows are composed first and handed to the file in one write, then flushed, so a
// run killed between calls leaves every earlier row complete; a kill during a call can at worst
// cut its last row short, which a reader recognises by the missing fields.

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace glossa::io {

class TraceWriter {
public:
  // Creates (or empties) `file` and writes the header; creates the parent directory if missing.
  // Throws std::runtime_error if the file cannot be written.
  explicit TraceWriter(const std::filesystem::path &file);

  // Throws std::invalid_argument (before writing anything) for a point name that CSV cannot
  // carry unquoted: empty, or containing ',', '"', '\n' or '\r'; std::runtime_error if writing
  // fails (e.g. a full disk).
  void append(double time, const std::vector<std::pair<std::string, Eigen::Vector3d>> &pointDisplacements);

private:
  std::filesystem::path file_;
  std::ofstream out_;
};

} // namespace glossa::io
