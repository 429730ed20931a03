#pragma once
// The step files of a run (results_steps/step_NNNNNN.h5, in step order), a field of the last
// written step (/step_*/<name>), and its largest magnitude: what the integration tests compare
// between runs.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "Hdf5Reading.hpp"

namespace glossa::test {

inline std::vector<std::filesystem::path> stepFiles(const std::filesystem::path &dir) {
  std::vector<std::filesystem::path> files;
  for (const auto &entry : std::filesystem::directory_iterator(dir / "results_steps"))
    if (entry.path().extension() == ".h5") files.push_back(entry.path());
  std::sort(files.begin(), files.end()); // zero-padded: name order is step order
  return files;
}

inline std::vector<double> lastStepField(const std::filesystem::path &dir, const std::string &name) {
  const io::testing::Hdf5File file(stepFiles(dir).back());
  std::string last;
  for (const auto &path : file.datasetPaths())
    if (path.rfind("/step_", 0) == 0 && path.size() > name.size() + 1 &&
        path.substr(path.size() - name.size() - 1) == "/" + name && path > last)
      last = path;
  return file.doubles(last).values;
}

inline double maxAbs(const std::vector<double> &v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

} // namespace glossa::test
