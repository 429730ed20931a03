#pragma once
// A fresh directory under the system's temporary directory, named for the test and the process
// (ctest runs test processes side by side), removed at the end (kept if GLOSSA_KEEP_SCRATCH is
// set, for debugging).

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <unistd.h>

namespace glossa::test {

class ScratchDir {
 public:
  explicit ScratchDir(const std::string &name)
      : path_(std::filesystem::temp_directory_path() / ("glossa_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    if (!std::getenv("GLOSSA_KEEP_SCRATCH")) std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir &) = delete;
  ScratchDir &operator=(const ScratchDir &) = delete;

  // Writes `content` byte for byte (so tests control CRLF and final newlines).
  std::string write(const std::string &name, const std::string &content) const {
    const std::string file = (path_ / name).string();
    std::ofstream(file, std::ios::binary) << content;
    return file;
  }
  std::string file(const std::string &name) const { return (path_ / name).string(); }
  const std::filesystem::path &path() const { return path_; }

 private:
  std::filesystem::path path_;
};

} // namespace glossa::test
