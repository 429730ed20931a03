#pragma once
// A fresh directory under the system temporary directory that every rank shares (rank 0 makes it
// and tells the others), removed afterwards: the run's files are written into one directory by
// all ranks, as a run's output directory is.

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

namespace glossa::testing {

class SharedScratch {
public:
  SharedScratch() : comm_(Tpetra::getDefaultComm()) {
    std::vector<char> name(4096, '\0');
    if (comm_->getRank() == 0) {
      std::string pattern = (std::filesystem::temp_directory_path() / "glossa_run_XXXXXX").string();
      if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
      std::copy(pattern.begin(), pattern.end(), name.begin());
    }
    Teuchos::broadcast(*comm_, 0, static_cast<int>(name.size()), name.data());
    path_ = std::string(name.data());
  }
  ~SharedScratch() {
    comm_->barrier();
    std::error_code ignored;
    if (comm_->getRank() == 0) std::filesystem::remove_all(path_, ignored);
  }
  SharedScratch(const SharedScratch &) = delete;
  SharedScratch &operator=(const SharedScratch &) = delete;

  const std::filesystem::path &path() const { return path_; }

private:
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::filesystem::path path_;
};

} // namespace glossa::testing
