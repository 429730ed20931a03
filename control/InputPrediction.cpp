#include "control/InputPrediction.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace glossa::control {

std::vector<double> linearPrediction(const std::vector<double> &previous, const std::vector<double> &older,
                                     GeneType geneType) {
  if (previous.size() != older.size()) {
    std::ostringstream s;
    s << "linearPrediction: " << previous.size() << " previous inputs and " << older.size() << " older ones";
    throw std::invalid_argument(s.str());
  }
  std::vector<double> u(previous.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    for (double v : {previous[i], older[i]})
      if (!(v >= 0.0 && v <= 1.0)) {
        std::ostringstream s;
        s << "linearPrediction: input " << i << " = " << v << " is out of range: allowed [0, 1]";
        throw std::invalid_argument(s.str());
      }
    u[i] = std::clamp(2.0 * previous[i] - older[i], 0.0, 1.0);
    if (geneType == GeneType::binary) u[i] = u[i] < 0.5 ? 0.0 : 1.0;
  }
  return u;
}

} // namespace glossa::control
