#include "control/MusclePruning.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace glossa::control {
namespace {

void checkGroup(int group, std::size_t groupCount, const char *where) {
  if (group < 0 || static_cast<std::size_t>(group) >= groupCount) {
    std::ostringstream s;
    s << where << ": group " << group << " is out of range: allowed [0, " << groupCount << ")";
    throw std::invalid_argument(s.str());
  }
}

}  // namespace

double fibreLengthMeasure(const Eigen::Matrix<double, 8, 3> &X, const Eigen::Vector3d &N) {
  const double norm = N.norm();
  if (!(norm > 0.0) || !std::isfinite(norm))
    throw std::invalid_argument("fibreLengthMeasure: the fibre direction is zero or not finite");
  const Eigen::Matrix<double, 8, 1> s = X * (N / norm);
  return s.maxCoeff() - s.minCoeff();
}

void GroupStretchSums::add(int group, double stretch, double fibreLength) {
  if (group == -1) return;
  checkGroup(group, groupCount(), "GroupStretchSums::add");
  if (!(stretch > 0.0) || !std::isfinite(stretch)) {
    std::ostringstream s;
    s << "GroupStretchSums::add: stretch = " << stretch << " is out of range: allowed (0, inf)";
    throw std::invalid_argument(s.str());
  }
  if (!(fibreLength >= 0.0) || !std::isfinite(fibreLength)) {
    std::ostringstream s;
    s << "GroupStretchSums::add: fibreLength = " << fibreLength << " is out of range: allowed [0, inf)";
    throw std::invalid_argument(s.str());
  }
  weightedStretch[group] += stretch * fibreLength;
  length[group] += fibreLength;
}

GroupStretchSums &GroupStretchSums::operator+=(const GroupStretchSums &other) {
  if (other.groupCount() != groupCount())
    throw std::invalid_argument("GroupStretchSums: adding sums over a different number of groups");
  for (std::size_t m = 0; m < groupCount(); ++m) {
    weightedStretch[m] += other.weightedStretch[m];
    length[m] += other.length[m];
  }
  return *this;
}

std::vector<double> GroupStretchSums::average() const {
  std::vector<double> lambdaBar(groupCount(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t m = 0; m < groupCount(); ++m)
    if (length[m] > 0.0) lambdaBar[m] = weightedStretch[m] / length[m];
  return lambdaBar;
}

std::vector<int> groupsInTension(const std::vector<double> &averageStretch,
                                 const std::vector<double> &referenceStretch, double tolerance,
                                 const std::vector<bool> &alwaysEvaluated) {
  const std::size_t n = averageStretch.size();
  if (referenceStretch.size() != n || alwaysEvaluated.size() != n) {
    std::ostringstream s;
    s << "groupsInTension: " << n << " average stretches, " << referenceStretch.size()
      << " reference stretches and " << alwaysEvaluated.size() << " always-evaluated flags";
    throw std::invalid_argument(s.str());
  }
  if (!(tolerance >= 0.0)) {
    std::ostringstream s;
    s << "groupsInTension: tolerance = " << tolerance << " is out of range: allowed [0, inf)";
    throw std::invalid_argument(s.str());
  }
  std::vector<int> evaluated;
  for (std::size_t m = 0; m < n; ++m) {
    const bool unknown = std::isnan(averageStretch[m]) || std::isnan(referenceStretch[m]);
    if (alwaysEvaluated[m] || unknown || averageStretch[m] > referenceStretch[m] + tolerance)
      evaluated.push_back(static_cast<int>(m));
  }
  return evaluated;
}

std::vector<double> inputsFromGenome(const std::vector<int> &evaluatedGroups, const Genome &genome,
                                     std::size_t groupCount) {
  if (genome.size() != evaluatedGroups.size()) {
    std::ostringstream s;
    s << "inputsFromGenome: " << genome.size() << " genes for " << evaluatedGroups.size()
      << " evaluated groups";
    throw std::invalid_argument(s.str());
  }
  std::vector<double> u(groupCount, 0.0);
  for (std::size_t i = 0; i < genome.size(); ++i) {
    checkGroup(evaluatedGroups[i], groupCount, "inputsFromGenome");
    u[evaluatedGroups[i]] = genome[i];
  }
  return u;
}

Genome genomeFromInputs(const std::vector<int> &evaluatedGroups, const std::vector<double> &inputs) {
  Genome g;
  g.reserve(evaluatedGroups.size());
  for (int m : evaluatedGroups) {
    checkGroup(m, inputs.size(), "genomeFromInputs");
    g.push_back(inputs[m]);
  }
  return g;
}

}  // namespace glossa::control
