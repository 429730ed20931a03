#pragma once
// A scratch directory of this test process's own, for the files a unit test writes and reads
// back. ctest -j runs the test processes side by side (each gtest case is its own process), and
// two of them writing one fixed file name raced: a reader saw the other process's half-written
// mesh. Made on first use, removed when the process ends.

#include <filesystem>

#include "ScratchDir.hpp"

namespace glossa::test {

inline const std::filesystem::path &processScratch() {
  static const ScratchDir directory("test");
  return directory.path();
}

} // namespace glossa::test
