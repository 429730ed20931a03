#pragma once
// Where a run's checkpoints live and how they are made durable (glossa run --restart):
// <output>/checkpoint/step_NNNNNN/rank_RRRR.cbor holds each rank's part of the state after
// committed step NNNNNN (nlohmann's CBOR: every double is stored as its 8 bytes, so a restored
// state is bit-identical), and <output>/checkpoint/latest names the newest complete one. Each
// part is written to a temporary file, fsync'ed and renamed; `latest` is replaced the same way
// only after every rank's part is on disk (the caller's barrier), so a run killed at any moment
// leaves `latest` naming a checkpoint whose every part is complete. Older checkpoints are
// removed once a newer one is published. No MPI here: the caller synchronises.

#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

namespace glossa::io {

class CheckpointStore {
public:
  explicit CheckpointStore(const std::filesystem::path &outputDirectory);

  // This rank's part of the checkpoint after step `step`. Throws OutputError if it cannot be written.
  void writePart(int step, int rank, const nlohmann::json &part) const;
  // Names checkpoint `step` the latest (after every rank's writePart) and removes the others.
  // One rank calls it.
  void publish(int step) const;

  // The step of the latest complete checkpoint, if there is one.
  std::optional<int> latestStep() const;
  // A rank's part of checkpoint `step`; throws OutputError naming the file if it is missing or
  // cannot be decoded.
  nlohmann::json readPart(int step, int rank) const;

  const std::filesystem::path &directory() const { return root_; }

private:
  std::filesystem::path stepDirectory(int step) const;
  std::filesystem::path root_; // <output>/checkpoint
};

} // namespace glossa::io
