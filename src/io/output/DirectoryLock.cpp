#include "io/output/DirectoryLock.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "io/output/OutputError.hpp"

namespace glossa::io {

DirectoryLock::DirectoryLock(const std::filesystem::path &dir) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / kFileName;
  // O_CLOEXEC: a child process (none today) must not keep the directory locked after the run.
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw OutputError("cannot open the lock file " + file.string() + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) {
    held_ = true;
    const std::string pid = std::to_string(::getpid()) + "\n";
    // The process id is a courtesy for the refusal's message: a failed write changes nothing.
    if (::ftruncate(fd_, 0) == 0) {
      [[maybe_unused]] const ssize_t n = ::pwrite(fd_, pid.data(), pid.size(), 0);
    }
    return;
  }
  if (errno != EWOULDBLOCK)
    throw OutputError("cannot lock " + file.string() + ": " + std::strerror(errno));
  std::ifstream(file) >> holder_;
}

DirectoryLock::~DirectoryLock() {
  if (fd_ >= 0) ::close(fd_); // releases the lock
}

} // namespace glossa::io
