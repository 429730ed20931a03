#pragma once
// traces.csv: one row per named point per written time, "time,point,ux,uy,uz", flushed after
// every call and with 17 significant digits (round-trip exact), for regression traces.

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace glossa::io {

class TraceWriter {
public:
  explicit TraceWriter(const std::filesystem::path &file);
  void append(double time, const std::vector<std::pair<std::string, Eigen::Vector3d>> &pointDisplacements);

private:
  std::ofstream out_;
};

} // namespace glossa::io
