// One run per output directory: a second holder is refused while the first lives, and the lock
// goes with its holder (as it goes with a killed process: the kernel closes its files).

#include <fstream>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "ScratchDirectory.hpp"
#include "io/output/DirectoryLock.hpp"

namespace glossa::io {
namespace {

using testing::ScratchDirectory;

TEST(DirectoryLock, ASecondHolderIsRefusedAndToldTheFirst) {
  ScratchDirectory scratch;
  const auto dir = scratch / "results" / "run";
  DirectoryLock first(dir);
  EXPECT_TRUE(first.held());
  EXPECT_TRUE(std::filesystem::is_directory(dir));
  // flock(2) locks belong to an open file: a second open conflicts even in the same process.
  DirectoryLock second(dir);
  EXPECT_FALSE(second.held());
  EXPECT_EQ(second.holder(), std::to_string(::getpid()));
}

TEST(DirectoryLock, TheLockGoesWithItsHolderAndItsFileStaysHarmless) {
  ScratchDirectory scratch;
  auto first = std::make_unique<DirectoryLock>(scratch.path());
  ASSERT_TRUE(first->held());
  first.reset();
  EXPECT_TRUE(std::filesystem::exists(scratch / DirectoryLock::kFileName));
  EXPECT_TRUE(DirectoryLock(scratch.path()).held());
}

TEST(DirectoryLock, AFileWhereTheDirectoryShouldBeIsAnError) {
  ScratchDirectory scratch;
  std::ofstream(scratch / "file") << "x";
  EXPECT_THROW(DirectoryLock(scratch / "file"), std::filesystem::filesystem_error);
}

} // namespace
} // namespace glossa::io
