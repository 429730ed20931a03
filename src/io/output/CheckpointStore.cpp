#include "io/output/CheckpointStore.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

#include "io/output/AtomicFile.hpp"
#include "io/output/CheckpointError.hpp"
#include "io/output/Crc32.hpp"
#include "io/output/OutputError.hpp"

namespace glossa::io {

namespace {
std::string numbered(const char *prefix, int n, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%s%0*d", prefix, digits, n);
  return text;
}

// Little-endian whatever the machine, so a checkpoint reads the same on any.
void putLittleEndian(std::string &out, std::uint64_t value, int bytes) {
  for (int k = 0; k < bytes; ++k) out.push_back(static_cast<char>((value >> (8 * k)) & 0xFFu));
}
std::uint64_t getLittleEndian(const std::string &in, std::size_t at, int bytes) {
  std::uint64_t value = 0;
  for (int k = 0; k < bytes; ++k) value |= static_cast<std::uint64_t>(static_cast<unsigned char>(in[at + k])) << (8 * k);
  return value;
}
} // namespace

CheckpointStore::CheckpointStore(const std::filesystem::path &outputDirectory) : root_(outputDirectory / "checkpoint") {}

std::filesystem::path CheckpointStore::stepDirectory(int step) const { return root_ / numbered("step_", step, 6); }

std::filesystem::path CheckpointStore::partPath(int step, int rank) const {
  return stepDirectory(step) / (numbered("rank_", rank, 4) + ".cbor");
}

std::string CheckpointStore::frame(int step, int rank, const std::string &cbor) {
  std::string bytes(kMagic, 8);
  putLittleEndian(bytes, kFormat, 4);
  putLittleEndian(bytes, static_cast<std::uint32_t>(rank), 4);
  putLittleEndian(bytes, static_cast<std::uint64_t>(step), 8);
  putLittleEndian(bytes, cbor.size(), 8);
  bytes += cbor;
  putLittleEndian(bytes, crc32(bytes), 4);
  return bytes;
}

std::string CheckpointStore::unframe(const std::string &bytes, int step, int rank) {
  const auto size = std::to_string(bytes.size()) + " bytes";
  if (bytes.size() < kHeaderBytes + kTrailerBytes || bytes.compare(0, 8, kMagic) != 0)
    throw CheckpointError("not a Glossa checkpoint part (" + size + ", without the header that begins \"" +
                          std::string(kMagic) + "\")");
  const std::uint64_t format = getLittleEndian(bytes, 8, 4), length = getLittleEndian(bytes, 24, 8);
  if (format != kFormat)
    throw CheckpointError("checkpoint format " + std::to_string(format) + ", this glossa reads format " +
                          std::to_string(kFormat));
  // The length first: a part cut short or run on is named as such, not as a checksum mismatch.
  if (length != bytes.size() - kHeaderBytes - kTrailerBytes)
    throw CheckpointError("the header announces " + std::to_string(length) + " bytes of state, the file holds " +
                          std::to_string(bytes.size() - kHeaderBytes - kTrailerBytes) + " (cut short or run on)");
  const std::uint32_t stored = static_cast<std::uint32_t>(getLittleEndian(bytes, bytes.size() - kTrailerBytes, 4));
  const std::uint32_t computed = crc32(std::string_view(bytes).substr(0, bytes.size() - kTrailerBytes));
  if (stored != computed) {
    char text[96];
    std::snprintf(text, sizeof text, "its CRC-32 is %08x, the file records %08x", computed, stored);
    throw CheckpointError(std::string("the file is damaged: ") + text);
  }
  // Checked after the CRC, so these name a part copied from elsewhere, not damage.
  const std::uint64_t partRank = getLittleEndian(bytes, 12, 4), partStep = getLittleEndian(bytes, 16, 8);
  if (partRank != static_cast<std::uint64_t>(rank) || partStep != static_cast<std::uint64_t>(step))
    throw CheckpointError("it is rank " + std::to_string(partRank) + "'s part of step " + std::to_string(partStep) +
                          ", not rank " + std::to_string(rank) + "'s of step " + std::to_string(step));
  return bytes.substr(kHeaderBytes, length);
}

void CheckpointStore::writePart(int step, int rank, const nlohmann::json &part) const {
  const std::filesystem::path dir = stepDirectory(step);
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw OutputError("cannot create " + dir.string() + ": " + error.message());
  const std::vector<std::uint8_t> cbor = nlohmann::json::to_cbor(part);
  replaceFileAtomically(partPath(step, rank),
                        frame(step, rank, std::string(reinterpret_cast<const char *>(cbor.data()), cbor.size())));
}

void CheckpointStore::publish(int step) const {
  const std::string name = stepDirectory(step).filename().string();
  replaceFileAtomically(root_ / "latest", name + "\n");
  // The older checkpoints (and any a killed run left half-written) are no longer needed.
  for (const auto &entry : std::filesystem::directory_iterator(root_)) {
    if (!entry.is_directory() || entry.path().filename() == name) continue;
    std::error_code ignored;
    std::filesystem::remove_all(entry.path(), ignored);
  }
}

std::optional<int> CheckpointStore::latestStep() const {
  const std::filesystem::path file = root_ / "latest";
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Exactly what publish writes: anything else is damage, not a checkpoint to guess at.
  static const std::regex name("step_([0-9]{6,9})\n");
  std::smatch match;
  if (!std::regex_match(text, match, name)) {
    std::string shown = text.substr(0, 40);
    for (char &c : shown)
      if (c < ' ' || c > '~') c = '?';
    throw CheckpointError("checkpoint index " + file.string() + " holds '" + shown +
                          "' (" + std::to_string(text.size()) + " bytes), not the name of a checkpoint (step_NNNNNN and a newline)");
  }
  return std::stoi(match[1].str());
}

nlohmann::json CheckpointStore::readPart(int step, int rank) const {
  const std::filesystem::path file = partPath(step, rank);
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw CheckpointError("checkpoint part " + file.string() + " is missing (" + (root_ / "latest").string() +
                          " names an incomplete checkpoint)");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try {
    return nlohmann::json::from_cbor(unframe(bytes, step, rank));
  } catch (const nlohmann::json::exception &e) {
    throw CheckpointError("checkpoint part " + file.string() + " cannot be decoded: " + e.what());
  } catch (const CheckpointError &e) {
    throw CheckpointError("checkpoint part " + file.string() + ": " + e.what());
  }
}

} // namespace glossa::io
