#pragma once
// Quasi-steady 1D airflow through the airway's cross-sections (doc/theory.md, "Airflow through
// the airway"; doc/airflow.md): the air enters from the nasal end at rest (a reservoir at the
// nasal pressure) and leaves at the tracheal end with the tracheal pressure as the last
// section's static pressure; in between, Bernoulli with the area change, separation past the
// narrowest section with a recovery coefficient, and a Poiseuille loss (airflow/SectionMarch).
// Given the two end pressures it finds the flow rate; given the nasal pressure and the flow
// rate, the pressures. A flow rate from the tracheal end to the nasal end (expiration) is the
// same model with the ends' roles exchanged: the tracheal pressure is then the reservoir's.
//
// Flow limitation: a wall of compliance C = dA/dp carries at most the wave-speed flow rate
// A sqrt(A / (rho C)) (the speed index u/c reaches 1, Shapiro; Dawson & Elliott). When the end
// pressures ask for more, the flow is choked at the section of the smallest such limit: Q is
// that limit whatever the tracheal pressure, the sections carry the pressures of the march at it,
// and the rest of the drop (choke drop) is not resolved by the model. Rigid walls (C = 0) have no
// limit: the rigid channel's Q grows as the square root of the pressure drop and never plateaus.
//
// A closed section (ChannelSection::closed, or an area of 0) carries no flow: Q = 0, the
// sections before the first closed one are at the nasal pressure, those after the last closed one
// at the tracheal pressure, and the closed ones (and any between them) at the mean of the two.

#include <vector>

#include "airflow/FlowChannel.hpp"

namespace glossa::airflow {

struct FlowSolution {
  double flowRate = 0.0;          // [m^3/s], > 0 from the nasal end to the tracheal end
  std::vector<double> pressure;   // the static pressure at each section [Pa]
  double nasalPressure = 0.0;     // [Pa]
  double trachealPressure = 0.0;  // [Pa]
  int throat = -1;                // the narrowest section; -1 when closed
  bool closed = false;
  int firstClosed = -1, lastClosed = -1;
  bool choked = false;
  int chokeSection = -1;          // where the wave-speed limit holds the flow
  double chokeDrop = 0.0;         // the drop past the choke the sections do not carry [Pa]
  int iterations = 0;             // of the flow-rate solve
};

class AirflowModel {
 public:
  // At least two sections, arc lengths strictly increasing, every area and compliance finite and
  // >= 0 (an area of 0 is closed); density > 0, viscosity >= 0, recovery coefficient in
  // [0, 1]. Otherwise std::invalid_argument naming the section or constant.
  AirflowModel(Channel channel, AirSettings air);

  // The flow rate the end pressures drive, and the pressures along the channel.
  FlowSolution withPressures(double nasalPressure, double trachealPressure) const;
  // The pressures a flow rate gives from the nasal pressure, the tracheal one among them.
  // std::domain_error for a flow rate that the channel cannot carry: through a closed section,
  // or above the wave-speed limit.
  FlowSolution withFlowRate(double nasalPressure, double flowRate) const;

  // The smallest wave-speed flow rate of the sections [m^3/s]; infinity when every wall is rigid.
  double waveSpeedLimit(int *section = nullptr) const;

  const Channel &channel() const { return channel_; }
  const AirSettings &air() const { return air_; }

 private:
  FlowSolution closedSolution(double nasalPressure, double trachealPressure) const;
  // The flow from a reservoir at `upstream` to the static pressure `downstream` <= upstream,
  // through `directed` (the channel in the flow's direction).
  FlowSolution drivenFlow(const Channel &directed, double upstream, double downstream) const;

  Channel channel_;
  Channel reversed_;  // the channel seen from the tracheal end, for flow towards the nose
  AirSettings air_;
  int firstClosed_ = -1, lastClosed_ = -1;
};

}  // namespace glossa::airflow
