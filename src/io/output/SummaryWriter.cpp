#include "io/output/SummaryWriter.hpp"

#include <utility>

namespace glossa::io {

SummaryWriter::SummaryWriter(std::filesystem::path file) : file_(std::move(file)) {}

void SummaryWriter::appendStep(const nlohmann::json &step) {
  nlohmann::json &steps = root_["steps"];
  if (steps.is_null()) steps = nlohmann::json::array();
  steps.push_back(step);
}

void SummaryWriter::write() const {
  stage(".tmp", Durability::synced);
  publish(".tmp");
}

void SummaryWriter::stage(const std::string &suffix, Durability durability) const {
  if (file_.has_parent_path()) std::filesystem::create_directories(file_.parent_path());
  const std::string text = root_.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + '\n';
  stageFile(file_.string() + suffix, file_, text, durability);
}

void SummaryWriter::publish(const std::string &suffix) const { publishFile(file_.string() + suffix, file_); }

} // namespace glossa::io
