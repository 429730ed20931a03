#include "io/output/AtomicFile.hpp"
#include "io/output/OutputError.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <unistd.h>

namespace glossa::io {

namespace {
[[noreturn]] void fail(const std::string &what, const std::filesystem::path &file, int error) {
  throw OutputError("cannot " + what + " " + file.string() + ": " + std::strerror(error));
}

// write(2) may write less than asked or be interrupted by a signal; loop until all is written.
void writeAll(int fd, std::string_view contents, const std::filesystem::path &file) {
  const char *p = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write", file, errno);
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}
} // namespace

std::filesystem::path temporaryPathFor(const std::filesystem::path &target) {
  std::filesystem::path temporary = target;
  temporary += ".tmp";
  return temporary;
}

void stageFile(const std::filesystem::path &temporary, const std::filesystem::path &target, std::string_view contents,
               Durability durability) {
  // Errors name the target (the file the user knows), not its temporary.
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("create", target, errno);
  try {
    writeAll(fd, contents, target);
    // Without fsync a crash of the machine (not just of the run) could leave the renamed file
    // empty on some file systems; the cost is one sync of a small file per call.
    if (durability == Durability::synced && ::fsync(fd) != 0) fail("sync", target, errno);
  } catch (...) {
    ::close(fd);
    ::unlink(temporary.c_str());
    throw;
  }
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    fail("close", target, error);
  }
}

void publishFile(const std::filesystem::path &temporary, const std::filesystem::path &target) {
  if (::rename(temporary.c_str(), target.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    fail("rename onto", target, error);
  }
}

void replaceFileAtomically(const std::filesystem::path &target, std::string_view contents) {
  const std::filesystem::path temporary = temporaryPathFor(target);
  stageFile(temporary, target, contents, Durability::synced);
  publishFile(temporary, target);
}

} // namespace glossa::io
