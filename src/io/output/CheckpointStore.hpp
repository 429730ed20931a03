#pragma once
// Where a run's checkpoints live and how they are made durable (glossa run --restart):
// <output>/checkpoint/step_NNNNNN/rank_RRRR.cbor holds each rank's part of the state after
// committed step NNNNNN, and <output>/checkpoint/latest names the newest complete one. Each
// part is written to a temporary file, fsync'ed and renamed; `latest` is replaced the same way
// only after every rank's part is on disk (the caller's barrier), so a run killed at any moment
// leaves `latest` naming a checkpoint whose every part is complete. Older checkpoints are
// removed once a newer one is published. No MPI here: the caller synchronises.
//
// A part proves itself: a 32-byte header (the magic "GLOSSACP", the format version, the rank and
// the step it belongs to, the length of what follows, all little-endian), the state as
// nlohmann's CBOR (every double stored in full, so a restored state is bit-identical), and the
// CRC-32 of everything before it (io::crc32). A part that is cut short, longer, flipped, another
// rank's or step's, or not a checkpoint at all is refused on reading (io::CheckpointError),
// before any of its values is used.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace glossa::io {

class CheckpointStore {
public:
  static constexpr char kMagic[9] = "GLOSSACP";
  static constexpr std::uint32_t kFormat = 1;
  static constexpr std::size_t kHeaderBytes = 32, kTrailerBytes = 4;

  explicit CheckpointStore(const std::filesystem::path &outputDirectory);

  // This rank's part of the checkpoint after step `step`. Throws OutputError if it cannot be written.
  void writePart(int step, int rank, const nlohmann::json &part) const;
  // Names checkpoint `step` the latest (after every rank's writePart) and removes the others.
  // One rank calls it.
  void publish(int step) const;

  // The step of the latest complete checkpoint; none if `latest` does not exist. Throws
  // CheckpointError if `latest` exists but does not name a checkpoint as publish writes it.
  std::optional<int> latestStep() const;
  // A rank's part of checkpoint `step`; throws CheckpointError naming the file if it is missing,
  // fails its checks (header, length, CRC) or cannot be decoded.
  nlohmann::json readPart(int step, int rank) const;
  std::filesystem::path partPath(int step, int rank) const;

  const std::filesystem::path &directory() const { return root_; }

  // A part's bytes as written (header, CBOR, CRC), and back: the CBOR, or CheckpointError with
  // what is wrong (without the file's name).
  static std::string frame(int step, int rank, const std::string &cbor);
  static std::string unframe(const std::string &bytes, int step, int rank);

private:
  std::filesystem::path stepDirectory(int step) const;
  std::filesystem::path root_; // <output>/checkpoint
};

} // namespace glossa::io
