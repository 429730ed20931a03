#include "io/output/SummaryWriter.hpp"

#include <utility>

#include "io/output/AtomicFile.hpp"

namespace glossa::io {

SummaryWriter::SummaryWriter(std::filesystem::path file) : file_(std::move(file)) {}

void SummaryWriter::appendStep(const nlohmann::json &step) {
  nlohmann::json &steps = root_["steps"];
  if (steps.is_null()) steps = nlohmann::json::array();
  steps.push_back(step);
}

void SummaryWriter::write() const {
  if (file_.has_parent_path()) std::filesystem::create_directories(file_.parent_path());
  const std::string text = root_.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + '\n';
  replaceFileAtomically(file_, text);
}

} // namespace glossa::io
