#pragma once
// The search for the airway's closing pressure Pcrit (doc/airway.md, "Pcrit"): the run raises the
// suction of the Airway section's `closing pressure load` along its time function, and after every
// converged step asks the lumen whether the airway closed. The first closing step brackets Pcrit
// between the last committed open state and that step; the bracket is then halved by steps from
// the last open committed state to its middle (a closed trial is never committed, an open one is),
// until the pressures at its two ends are within `closing pressure tolerance`. A run that reaches
// its end time open says so. Eigen and JSON only: the Simulation hands it the tongue's vertices.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "loads/PressureField.hpp"
#include "model/AirwayOutput.hpp"

namespace glossa::solvers {

// 1 cmH2O in Pa (a water column of 1 cm at standard gravity).
inline constexpr double kPascalPerCmH2O = 98.0665;

class PcritSearch {
public:
  // `pressure`: the load's field; the search reports its largest value over the face set,
  // p_max b(t) (the uniform pressure, or the linear profile's at P_P).
  PcritSearch(const model::AirwayOutput &airway, loads::PressureField pressure, std::string loadName);

  double pressure(double t) const { return pressure_.pMax() * pressure_.timeFactor(t); }

  // The closed section of least area at the tongue's vertices `positions`; none if the lumen is open.
  std::optional<int> closedSection(const std::vector<Eigen::Vector3d> &positions) const;

  // A committed open state at time t; a converged trial at time t that closes `section`.
  void opened(double t);
  void closed(double t, int section);
  bool bracketing() const { return high_.has_value(); }
  // The bracket's pressures are within the tolerance: Pcrit is found.
  bool found() const;
  // From the last open committed state at `committed` (after a restart, the checkpoint's time,
  // which the search did not see committed) to the bracket's middle [s].
  double nextStep(double committed) const { return 0.5 * (*high_ - committed); }

  // summary.json's "pcrit": the bracket in cmH2O and Pa, the section, the solves it took; or,
  // never closed, that, the suction at `reached` (the last committed time) and the deck's
  // largest, at `endTime` (more when the run stopped short of it).
  nlohmann::json summary(double reached, double endTime) const;
  // The log's line at the end of the run.
  std::string line(double reached, double endTime) const;

private:
  const model::AirwayOutput &airway_;
  loads::PressureField pressure_;
  std::string loadName_;
  double low_ = 0.0;           // the last open committed time
  std::optional<double> high_; // the earliest closing trial's time
  int section_ = -1;
  int bisectionSteps_ = 0; // trials made inside the bracket
};

} // namespace glossa::solvers
