#pragma once
// A CSV time series keyed by name: "time [s],<key>,<value columns...>", one row per key per call
// (traces.csv keys by point, activation.csv by muscle group). Numbers with 17 significant digits
// (they read back bit-exactly, which the regression suite relies on). Rank 0 writes.
//
// Each call's rows are composed first and handed to the file in one write(2) (no buffer held
// back), so a run killed between calls leaves every earlier row complete; a kill during a call can
// at worst cut its last row short, which a reader recognises by the missing fields. A write that
// fails (a full disk, a file size limit) is cut back to the rows before it, so the file ends at a
// complete row, and throws OutputError naming the file.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace glossa::io {

class KeyedCsvWriter {
public:
  // Creates (or empties) `file` and writes the header "time [s],<keyColumn>,<valueColumns>"
  // (value columns named with their unit, "ux [m]"); creates
  // the parent directory if missing. Throws std::runtime_error if the file cannot be written.
  // `resumeAt` (a restart): the file is kept, cut back to that many bytes (what bytes() said at
  // the checkpoint: rows written after it, perhaps cut short by a kill, go), and appended to;
  // std::runtime_error if it is shorter than that.
  KeyedCsvWriter(const std::filesystem::path &file, const std::string &keyColumn,
                 const std::vector<std::string> &valueColumns, std::optional<std::uintmax_t> resumeAt = std::nullopt);
  ~KeyedCsvWriter();
  KeyedCsvWriter(const KeyedCsvWriter &) = delete;
  KeyedCsvWriter &operator=(const KeyedCsvWriter &) = delete;

  // Each row: a key and one value per value column. Throws std::invalid_argument (before writing
  // anything) for a key that CSV cannot carry unquoted (empty, or containing ',', '"', '\n' or
  // '\r') or a row of the wrong width; std::runtime_error if writing fails (e.g. a full disk).
  void append(double time, const std::vector<std::pair<std::string, std::vector<double>>> &rows);

  const std::filesystem::path &file() const { return file_; }
  // The file's length so far: every complete row.
  std::uintmax_t bytes() const { return bytes_; }

private:
  // Writes all of `text` after the complete rows, or cuts the file back to them and throws.
  void writeRows(const std::string &text);

  std::filesystem::path file_;
  std::string keyColumn_;
  std::size_t width_;
  std::uintmax_t bytes_ = 0;
  int fd_ = -1;
};

} // namespace glossa::io
