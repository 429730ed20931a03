#pragma once
// summary.json: the run's figures (converged, ranks, dofs, elements, wall_seconds, one record
// per step, final displacements). The caller edits root() and calls write() whenever the file
// should reflect progress; write() replaces the file atomically (AtomicFile.hpp), so the file
// on disk is always complete JSON, from either the previous or the latest write(). Rank 0 writes.

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "io/output/AtomicFile.hpp"

namespace glossa::io {

class SummaryWriter {
public:
  // Nothing is written until write(); `file` is the full path, e.g. <output>/summary.json.
  explicit SummaryWriter(std::filesystem::path file);

  nlohmann::json &root() { return root_; }
  const nlohmann::json &root() const { return root_; }

  // Appends to root()["steps"] (created as an array when absent).
  void appendStep(const nlohmann::json &step);

  // Creates the parent directory if missing. Non-finite numbers come out as null (JSON has no
  // NaN); invalid UTF-8 in strings is replaced rather than failing the run at its last moment.
  // Throws std::runtime_error if the file cannot be written.
  void write() const;
  // write() in its two halves (AtomicFile.hpp): stage writes the file as "<file><suffix>", publish
  // renames that onto the file. For a writer that must decide in between whether it still applies.
  void stage(const std::string &suffix, Durability durability) const;
  void publish(const std::string &suffix) const;

  const std::filesystem::path &file() const { return file_; }

private:
  std::filesystem::path file_;
  nlohmann::json root_ = nlohmann::json::object();
};

} // namespace glossa::io
