#include "io/output/TraceWriter.hpp"

#include <stdexcept>

namespace glossa::io {

TraceWriter::TraceWriter(const std::filesystem::path &file) : out_(file, std::ios::trunc) {
  if (!out_) throw std::runtime_error("cannot write " + file.string());
  out_.precision(17);
  out_ << "time,point,ux,uy,uz\n" << std::flush;
}

void TraceWriter::append(double time, const std::vector<std::pair<std::string, Eigen::Vector3d>> &points) {
  for (const auto &[name, u] : points) out_ << time << ',' << name << ',' << u.x() << ',' << u.y() << ',' << u.z() << '\n';
  out_.flush();
}

} // namespace glossa::io
