#pragma once
// summary.json: the run's figures, rewritten atomically (temporary file + rename) whenever the
// caller asks, so the file on disk is always complete JSON.

#include <filesystem>

#include <nlohmann/json.hpp>

namespace glossa::io {

class SummaryWriter {
public:
  explicit SummaryWriter(std::filesystem::path file) : file_(std::move(file)) {}
  nlohmann::json &root() { return root_; }
  void appendStep(const nlohmann::json &step) { root_["steps"].push_back(step); }
  void write() const;

private:
  std::filesystem::path file_;
  nlohmann::json root_ = nlohmann::json::object();
};

} // namespace glossa::io
