#include "io/output/KeyedCsvWriter.hpp"
#include "io/output/OutputError.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

#include "io/output/RoundTripText.hpp"

namespace glossa::io {

namespace {
[[noreturn]] void cannot(const char *what, const std::filesystem::path &file, int error) {
  throw OutputError(std::string("cannot ") + what + " " + file.string() + ": " + std::strerror(error));
}
} // namespace

KeyedCsvWriter::KeyedCsvWriter(const std::filesystem::path &file, const std::string &keyColumn,
                               const std::vector<std::string> &valueColumns, std::optional<std::uintmax_t> resumeAt)
    : file_(file), keyColumn_(keyColumn), width_(valueColumns.size()) {
  if (resumeAt) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(file_, error);
    if (error || size < *resumeAt)
      throw OutputError("cannot resume " + file_.string() + ": it is " + (error ? "missing" : "shorter than at the checkpoint"));
    std::filesystem::resize_file(file_, *resumeAt);
    fd_ = ::open(file_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd_ < 0) cannot("open", file_, errno);
    bytes_ = *resumeAt;
    return;
  }
  if (file_.has_parent_path()) std::filesystem::create_directories(file_.parent_path());
  fd_ = ::open(file_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) cannot("create", file_, errno);
  std::string header = "time [s]," + keyColumn;
  for (const auto &c : valueColumns) header += ',' + c;
  header += '\n';
  writeRows(header);
}

KeyedCsvWriter::~KeyedCsvWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void KeyedCsvWriter::writeRows(const std::string &text) {
  const char *p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      // Part of a row may have gone in before the disk filled up: the file ends at the last
      // complete row, as a reader expects.
      [[maybe_unused]] const int cut = ::ftruncate(fd_, static_cast<off_t>(bytes_));
      cannot("write", file_, error);
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  bytes_ += text.size();
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
  writeRows(text);
}

} // namespace glossa::io
