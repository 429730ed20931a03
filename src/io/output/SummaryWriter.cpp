#include "io/output/SummaryWriter.hpp"

#include <fstream>
#include <stdexcept>

namespace glossa::io {

void SummaryWriter::write() const {
  std::filesystem::path temporary = file_;
  temporary += ".tmp";
  {
    std::ofstream out(temporary);
    out << root_.dump(2) << '\n';
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::filesystem::rename(temporary, file_);
}

} // namespace glossa::io
