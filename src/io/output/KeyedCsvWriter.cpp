#include "io/output/KeyedCsvWriter.hpp"
#include "io/output/OutputError.hpp"

#include <stdexcept>

#include "io/output/RoundTripText.hpp"

namespace glossa::io {

KeyedCsvWriter::KeyedCsvWriter(const std::filesystem::path &file, const std::string &keyColumn,
                               const std::vector<std::string> &valueColumns, std::optional<std::uintmax_t> resumeAt)
    : file_(file), keyColumn_(keyColumn), width_(valueColumns.size()) {
  if (resumeAt) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(file_, error);
    if (error || size < *resumeAt)
      throw OutputError("cannot resume " + file_.string() + ": it is " + (error ? "missing" : "shorter than at the checkpoint"));
    std::filesystem::resize_file(file_, *resumeAt);
    out_.open(file_, std::ios::out | std::ios::app);
    bytes_ = *resumeAt;
    if (!out_) throw OutputError("cannot write " + file_.string());
    return;
  }
  if (file_.has_parent_path()) std::filesystem::create_directories(file_.parent_path());
  out_.open(file_, std::ios::out | std::ios::trunc);
  std::string header = "time [s]," + keyColumn;
  for (const auto &c : valueColumns) header += ',' + c;
  header += '\n';
  out_ << header << std::flush;
  bytes_ = header.size();
  if (!out_) throw OutputError("cannot write " + file_.string());
}

void KeyedCsvWriter::append(double time, const std::vector<std::pair<std::string, std::vector<double>>> &rows) {
  for (const auto &[key, values] : rows) {
    if (key.empty() || key.find_first_of(",\"\n\r") != std::string::npos)
      throw std::invalid_argument(file_.filename().string() + ": " + keyColumn_ + " name '" + key +
                                  "' must be non-empty and contain no ',', '\"' or line break");
    if (values.size() != width_)
      throw std::invalid_argument(file_.filename().string() + ": row '" + key + "' has " +
                                  std::to_string(values.size()) + " values, the header " + std::to_string(width_));
  }
  const std::string t = roundTripText(time);
  std::string text;
  for (const auto &[key, values] : rows) {
    text += t + ',' + key;
    for (double v : values) text += ',' + roundTripText(v);
    text += '\n';
  }
  out_.write(text.data(), static_cast<std::streamsize>(text.size()));
  out_.flush();
  if (!out_) throw OutputError("cannot write " + file_.string());
  bytes_ += text.size();
}

} // namespace glossa::io
