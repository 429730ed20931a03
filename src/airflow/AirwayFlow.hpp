#pragma once
// The flow through the airway's lumen as measured (doc/airflow.md): the lumen's sections become
// the channel of the 1D flow (airflow/AirflowModel), the flow's pressures are given back at every
// section, and from them the pressure at each Gauss point of the airway faces, through the face's
// arc length along the centreline at rest (airflow/CentrelinePressure).
//  - A section the lumen could not measure is left out of the channel; its pressure is
//    interpolated linearly in arc length between the measured sections around it (the end one's
//    beyond them).
//  - A closed section carries no flow (AirflowModel).
//  - The walls are rigid within one flow solve (compliance 0): the solid's give is the coupling's
//    business, not the flow model's.
// The arc lengths of the faces' Gauss points are fixed once, from their reference positions, as
// the loads' spatial profiles are (loads/PressureField). Eigen only.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "airflow/AirflowModel.hpp"
#include "airflow/CentrelinePressure.hpp"
#include "airway/AirwayLumen.hpp"

namespace glossa::airflow {

// What drives the flow at one time: the nasal pressure and either the tracheal pressure or the
// flow rate.
struct FlowDrive {
  double nasalPressure = 0.0;     // [Pa]
  bool byFlowRate = false;
  double trachealPressure = 0.0;  // [Pa], !byFlowRate
  double flowRate = 0.0;          // [m^3/s], byFlowRate
};

struct AirwayFlowState {
  FlowSolution flow;                    // over the channel's (measured) sections
  std::vector<double> sectionPressure;  // at every section of the lumen [Pa]
  std::vector<int> channelSections;     // the lumen's section of each channel section
  int smallest = -1;                    // the lumen's smallest measured section
  double smallestArea = 0.0;            // [m^2]
};

class AirwayFlow {
 public:
  // `faceGaussPoints`: the reference positions of the Gauss points of each airway face.
  AirwayFlow(const airway::Centreline &centreline, const std::vector<std::array<Eigen::Vector3d, 4>> &faceGaussPoints,
             AirSettings air, PressureMapping mapping);

  // The flow through `lumen` (measured from the lumen's sections) under `drive`. Throws
  // std::invalid_argument when fewer than two sections are measured, std::domain_error for a
  // flow rate the lumen cannot carry (AirflowModel::withFlowRate).
  AirwayFlowState solve(const airway::LumenState &lumen, const FlowDrive &drive) const;

  // The pressure at every Gauss point of every face from the sections' pressures.
  std::vector<std::array<double, 4>> facePressures(const std::vector<double> &sectionPressure) const;

  std::size_t numSections() const { return arcLengths_.size(); }
  const AirSettings &air() const { return air_; }

 private:
  std::vector<double> arcLengths_;
  CentrelinePressure centreline_;
  std::vector<std::array<double, 4>> gaussArcLength_;
  AirSettings air_;
  PressureMapping mapping_;
};

}  // namespace glossa::airflow
