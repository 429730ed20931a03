#pragma once
// Open MPI 4.1 gives every isolated singleton (a process started without mpiexec under
// OMPI_MCA_ess_singleton_isolated=1, the test suite's fast start, doc/developing.md) the same job
// family, so processes started side by side share one session directory,
// <tmp>/ompi.<host>.<uid>/jf.0, and race on making and removing it: MPI_Init then aborts with
// "mkdir ... File exists" (1 start in 400, four at once, measured). Such a process gets a session
// base directory of its own, <tmp>/glossa-ompi-<pid> (none in 800 starts), removed when the process
// ends. Anything else (mpiexec's ranks, a base directory the user chose) is left as it is. Call it
// before MPI is initialised. Standard library and POSIX only.

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include <unistd.h>

namespace glossa::app {

inline void separateIsolatedSingletonSession() {
  const char *isolated = std::getenv("OMPI_MCA_ess_singleton_isolated");
  if (!isolated || std::string(isolated) != "1") return;
  if (std::getenv("OMPI_MCA_orte_tmpdir_base") || std::getenv("OMPI_COMM_WORLD_SIZE")) return;
  struct Base {
    std::filesystem::path path;
    Base() {
      std::error_code error;
      const std::filesystem::path tmp = std::filesystem::temp_directory_path(error);
      if (error) return;
      path = tmp / ("glossa-ompi-" + std::to_string(::getpid()));
      std::filesystem::create_directories(path, error);
      if (error || ::setenv("OMPI_MCA_orte_tmpdir_base", path.c_str(), 1) != 0) path.clear();
    }
    ~Base() { // after main, MPI finalised
      std::error_code ignored;
      if (!path.empty()) std::filesystem::remove_all(path, ignored);
    }
  };
  static const Base base;
}

} // namespace glossa::app
