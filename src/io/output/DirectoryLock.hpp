#pragma once
// One run per output directory: two runs writing into one directory mix their files (one's
// summary and checkpoint, the other's CSVs). A run holds an exclusive flock(2) on
// "<directory>/.glossa.lock" for its whole life; the kernel releases it when the process ends,
// however it ends, so a killed run's lock file never blocks the next run. The file itself stays
// (it holds the holder's process id, for the refusal's message).

#include <filesystem>
#include <string>

namespace glossa::io {

class DirectoryLock {
public:
  // Creates `dir` if needed (std::filesystem::filesystem_error if it cannot) and tries the lock
  // without waiting; OutputError if the lock file cannot be opened.
  explicit DirectoryLock(const std::filesystem::path &dir);
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock &) = delete;
  DirectoryLock &operator=(const DirectoryLock &) = delete;

  // Whether this process holds the directory; if not, another process does.
  bool held() const { return held_; }
  // The holder's process id as its lock file says ("" if unreadable): for the refusal.
  const std::string &holder() const { return holder_; }

  static constexpr const char *kFileName = ".glossa.lock";

private:
  int fd_ = -1;
  bool held_ = false;
  std::string holder_;
};

} // namespace glossa::io
