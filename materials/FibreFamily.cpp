#include "materials/FibreFamily.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace glossa::materials {

std::vector<FibreFamily> equalFractionFamilies(const std::vector<Eigen::Vector3d> &directions,
                                               double totalFraction) {
  if (!(totalFraction >= 0.0 && totalFraction <= 1.0))
    throw std::invalid_argument("fibre families: total fibre fraction must be in [0, 1]");
  std::vector<FibreFamily> families;
  families.reserve(directions.size());
  for (const Eigen::Vector3d &d : directions) {
    const double n = d.norm();
    if (!(n > 1e-12) || !std::isfinite(n))
      throw std::invalid_argument("fibre families: a fibre direction has zero length");
    families.push_back({d / n, totalFraction / static_cast<double>(directions.size())});
  }
  return families;
}

double validateFibreFamilies(const std::vector<FibreFamily> &families) {
  double sum = 0.0;
  for (std::size_t f = 0; f < families.size(); ++f) {
    const std::string which = "fibre family " + std::to_string(f) + ": ";
    if (!(std::abs(families[f].N.norm() - 1.0) <= 1e-10))
      throw std::invalid_argument(which + "direction N must be a unit vector");
    const double phi = families[f].volumeFraction;
    if (!(phi >= 0.0 && phi <= 1.0)) throw std::invalid_argument(which + "volume fraction must be in [0, 1]");
    sum += phi;
  }
  if (!(sum <= 1.0 + 1e-12))
    throw std::invalid_argument("fibre families: volume fractions sum to more than 1");
  return std::max(0.0, 1.0 - sum);
}

}  // namespace glossa::materials
