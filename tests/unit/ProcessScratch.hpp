#pragma once
// A directory of this test process's own under the system's temporary directory, for the files a
// unit test writes and reads back. ctest -j runs the test processes side by side (each gtest case
// is its own process), and two of them writing one fixed file name raced: a reader saw the other
// process's half-written mesh. Made on first use, removed when the process ends.

#include <filesystem>
#include <string>
#include <system_error>

#include <gtest/gtest.h>
#include <unistd.h>

namespace glossa::test {

inline const std::filesystem::path &processScratch() {
  struct Directory {
    std::filesystem::path path;
    Directory() : path(std::filesystem::path(::testing::TempDir()) / ("glossa-test-" + std::to_string(::getpid()))) {
      std::filesystem::create_directories(path);
    }
    ~Directory() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Directory directory;
  return directory.path;
}

} // namespace glossa::test
