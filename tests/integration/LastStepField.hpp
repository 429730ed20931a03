#pragma once
// A field of the last written step (/step_*/<name>) in a run's results.h5, and its largest
// magnitude: what the integration tests compare between runs.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "Hdf5Reading.hpp"

namespace glossa::test {

inline std::vector<double> lastStepField(const std::filesystem::path &dir, const std::string &name) {
  const io::testing::Hdf5File file(dir / "results.h5");
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
