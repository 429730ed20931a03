#include "io/output/TraceWriter.hpp"

#include <stdexcept>

#include "io/output/RoundTripText.hpp"

namespace glossa::io {

TraceWriter::TraceWriter(const std::filesystem::path &file) : file_(file) {
  if (file_.has_parent_path()) std::filesystem::create_directories(file_.parent_path());
  out_.open(file_, std::ios::out | std::ios::trunc);
  out_ << "time,point,ux,uy,uz\n" << std::flush;
  if (!out_) throw std::runtime_error("TraceWriter: cannot write " + file_.string());
}

void TraceWriter::append(double time, const std::vector<std::pair<std::string, Eigen::Vector3d>> &pointDisplacements) {
  for (const auto &[name, u] : pointDisplacements)
    if (name.empty() || name.find_first_of(",\"\n\r") != std::string::npos)
      throw std::invalid_argument("TraceWriter: point name '" + name +
                                  "' must be non-empty and contain no ',', '\"' or line break");
  const std::string t = roundTripText(time);
  std::string rows;
  for (const auto &[name, u] : pointDisplacements)
    rows += t + ',' + name + ',' + roundTripText(u.x()) + ',' + roundTripText(u.y()) + ',' + roundTripText(u.z()) +
            '\n';
  out_.write(rows.data(), static_cast<std::streamsize>(rows.size()));
  out_.flush();
  if (!out_) throw std::runtime_error("TraceWriter: cannot write " + file_.string());
}

} // namespace glossa::io
