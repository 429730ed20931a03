#pragma once
// A full disk for a test: `body` runs in a child process under RLIMIT_FSIZE (SIGXFSZ ignored, as
// glossa ignores it: a write past the limit fails with EFBIG, as one on a full disk fails with
// ENOSPC), and the child's fate comes back. The limit never touches the test process itself.

#include <csignal>
#include <cstdlib>
#include <functional>
#include <string>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace glossa::io::testing {

// "exit N" or "signal S": how the child that ran `body` (its exit status) ended. The child ends
// with std::exit, so libraries close what they hold as in a real run (HDF5 crashed there).
inline std::string underFileSizeLimit(rlim_t bytes, const std::function<int()> &body) {
  const pid_t child = ::fork();
  if (child < 0) return "no child";
  if (child == 0) {
    const rlimit limit{bytes, bytes};
    ::signal(SIGXFSZ, SIG_IGN);
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(100);
    std::exit(body());
  }
  int status = 0;
  if (::waitpid(child, &status, 0) != child) return "lost child";
  if (WIFSIGNALED(status)) return "signal " + std::to_string(WTERMSIG(status));
  return "exit " + std::to_string(WEXITSTATUS(status));
}

} // namespace glossa::io::testing
