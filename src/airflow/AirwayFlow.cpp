#include "airflow/AirwayFlow.hpp"

#include <stdexcept>
#include <string>

namespace glossa::airflow {

namespace {
std::vector<Eigen::Vector3d> centres(const airway::Centreline &c) {
  std::vector<Eigen::Vector3d> x;
  for (const auto &plane : c.planes) x.push_back(plane.origin);
  return x;
}
}  // namespace

AirwayFlow::AirwayFlow(const airway::Centreline &centreline,
                       const std::vector<std::array<Eigen::Vector3d, 4>> &faceGaussPoints, AirSettings air,
                       PressureMapping mapping)
    : arcLengths_(centreline.arcLength), centreline_(centres(centreline), centreline.arcLength), air_(air),
      mapping_(mapping) {
  gaussArcLength_.reserve(faceGaussPoints.size());
  for (const auto &face : faceGaussPoints) {
    std::array<double, 4> s{};
    for (int q = 0; q < 4; ++q) s[q] = centreline_.arcLengthOf(face[q]);
    gaussArcLength_.push_back(s);
  }
}

AirwayFlowState AirwayFlow::solve(const airway::LumenState &lumen, const FlowDrive &drive) const {
  if (lumen.sections.size() != arcLengths_.size())
    throw std::invalid_argument("airway flow: " + std::to_string(lumen.sections.size()) + " sections measured for " +
                                std::to_string(arcLengths_.size()) + " on the centreline");
  AirwayFlowState out;
  Channel channel;
  for (std::size_t k = 0; k < lumen.sections.size(); ++k) {
    const airway::SectionState &section = lumen.sections[k];
    if (!section.measured) continue;
    channel.push_back({arcLengths_[k], section.lumen.area, 0.0, section.closed});
    out.channelSections.push_back(static_cast<int>(k));
  }
  if (channel.size() < 2)
    throw std::invalid_argument("airway flow: " + std::to_string(channel.size()) + " of the lumen's " +
                                std::to_string(lumen.sections.size()) +
                                " sections measured; the flow needs at least two");
  out.smallest = lumen.smallest;
  if (lumen.smallest >= 0) out.smallestArea = lumen.sections[static_cast<std::size_t>(lumen.smallest)].area();
  const AirflowModel model(std::move(channel), air_);
  out.flow = drive.byFlowRate ? model.withFlowRate(drive.nasalPressure, drive.flowRate)
                              : model.withPressures(drive.nasalPressure, drive.trachealPressure);
  // Every section's pressure: the channel's where measured, linear in arc length between them.
  const std::vector<int> &at = out.channelSections;
  out.sectionPressure.assign(arcLengths_.size(), 0.0);
  std::size_t next = 0;  // the first channel section at or after k
  for (std::size_t k = 0; k < arcLengths_.size(); ++k) {
    while (next < at.size() && static_cast<std::size_t>(at[next]) < k) ++next;
    if (next < at.size() && static_cast<std::size_t>(at[next]) == k) {
      out.sectionPressure[k] = out.flow.pressure[next];
    } else if (next == 0) {
      out.sectionPressure[k] = out.flow.pressure.front();
    } else if (next == at.size()) {
      out.sectionPressure[k] = out.flow.pressure.back();
    } else {
      const double s0 = arcLengths_[static_cast<std::size_t>(at[next - 1])];
      const double s1 = arcLengths_[static_cast<std::size_t>(at[next])];
      const double t = (arcLengths_[k] - s0) / (s1 - s0);
      out.sectionPressure[k] = (1.0 - t) * out.flow.pressure[next - 1] + t * out.flow.pressure[next];
    }
  }
  return out;
}

std::vector<std::array<double, 4>> AirwayFlow::facePressures(const std::vector<double> &sectionPressure) const {
  std::vector<std::array<double, 4>> p(gaussArcLength_.size());
  for (std::size_t f = 0; f < p.size(); ++f)
    for (int q = 0; q < 4; ++q) p[f][q] = centreline_.pressureAtArcLength(gaussArcLength_[f][q], sectionPressure, mapping_);
  return p;
}

}  // namespace glossa::airflow
