#pragma once
// The airflow's pressure on a face of the airway wall, from the face's position along the
// centreline: the point (e.g. the face's centre) is projected onto the centreline, the polyline
// through the sections' centres, and its arc length there is read off (linearly along the
// segment it falls on, between the two sections' arc lengths; before the first section and past
// the last, the end section's). The pressure at that arc length is the nearest section's, or
// interpolated linearly in arc length between the two sections around it (constant beyond the
// ends).

#include <Eigen/Core>
#include <vector>

namespace glossa::airflow {

enum class PressureMapping { nearestSection, linear };

class CentrelinePressure {
 public:
  // One centre and arc length per section, at least one section, arc lengths strictly increasing;
  // otherwise std::invalid_argument.
  CentrelinePressure(std::vector<Eigen::Vector3d> centres, std::vector<double> arcLengths);

  // The arc length of the centreline's point nearest x [m].
  double arcLengthOf(const Eigen::Vector3d &x) const;
  // The pressure at arc length s from the sections' pressures (one per section).
  double pressureAtArcLength(double s, const std::vector<double> &pressures, PressureMapping mapping) const;
  double pressureAt(const Eigen::Vector3d &x, const std::vector<double> &pressures, PressureMapping mapping) const {
    return pressureAtArcLength(arcLengthOf(x), pressures, mapping);
  }

  std::size_t numSections() const { return arcLengths_.size(); }

 private:
  std::vector<Eigen::Vector3d> centres_;
  std::vector<double> arcLengths_;
};

}  // namespace glossa::airflow
