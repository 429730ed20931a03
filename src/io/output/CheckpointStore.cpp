#include "io/output/CheckpointStore.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/output/AtomicFile.hpp"
#include "io/output/OutputError.hpp"

namespace glossa::io {

namespace {
std::string numbered(const char *prefix, int n, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%s%0*d", prefix, digits, n);
  return text;
}
std::filesystem::path partFile(const std::filesystem::path &stepDirectory, int rank) {
  return stepDirectory / (numbered("rank_", rank, 4) + ".cbor");
}
} // namespace

CheckpointStore::CheckpointStore(const std::filesystem::path &outputDirectory) : root_(outputDirectory / "checkpoint") {}

std::filesystem::path CheckpointStore::stepDirectory(int step) const { return root_ / numbered("step_", step, 6); }

void CheckpointStore::writePart(int step, int rank, const nlohmann::json &part) const {
  const std::filesystem::path dir = stepDirectory(step);
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) throw OutputError("cannot create " + dir.string() + ": " + error.message());
  const std::vector<std::uint8_t> bytes = nlohmann::json::to_cbor(part);
  replaceFileAtomically(partFile(dir, rank),
                        std::string_view(reinterpret_cast<const char *>(bytes.data()), bytes.size()));
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
  std::ifstream in(root_ / "latest");
  std::string name;
  if (!(in >> name) || name.rfind("step_", 0) != 0) return std::nullopt;
  try {
    return std::stoi(name.substr(5));
  } catch (const std::exception &) {
    throw OutputError((root_ / "latest").string() + " names '" + name + "', not a checkpoint");
  }
}

nlohmann::json CheckpointStore::readPart(int step, int rank) const {
  const std::filesystem::path file = partFile(stepDirectory(step), rank);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw OutputError("checkpoint part " + file.string() + " is missing");
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try {
    return nlohmann::json::from_cbor(bytes);
  } catch (const nlohmann::json::exception &e) {
    throw OutputError("checkpoint part " + file.string() + " cannot be read: " + e.what());
  }
}

} // namespace glossa::io
