#pragma once
// The static pressures along the channel for a given flow rate, in the direction of the flow
// (doc/theory.md, "Airflow through the airway"): from an upstream reservoir (air at rest at
// pressure P_up) into the first section without loss,
//   p_0 = P_up - rho Q^2 / (2 A_0^2),
// then from section j to j+1 Bernoulli's change of the dynamic pressure, all of it up to the
// narrowest section m, the recovery coefficient c_r of it past m (the jet separates at the throat
// and does not refill the widening channel), less the Poiseuille loss of a circular tube of the
// same area (equivalent radius sqrt(A/pi)), integrated by the trapezoidal rule in 1/A^2:
//   p_{j+1} = p_j + c_j rho Q^2 / 2 (1/A_j^2 - 1/A_{j+1}^2) - 8 pi mu Q L_j (1/A_j^2 + 1/A_{j+1}^2) / 2,
// c_j = 1 for j < m, c_r for j >= m, L_j = s_{j+1} - s_j. Q >= 0 runs from section 0 to the last.

#include <vector>

#include "airflow/FlowChannel.hpp"

namespace glossa::airflow {

// The index of the narrowest section (the first of equal areas); the channel has no closed section.
int throatOf(const Channel &channel);

struct SectionDrops {
  double entry = 0.0;              // P_up - p_0 [Pa]
  std::vector<double> rise;        // p_{j+1} - p_j, one per segment [Pa]
  double entrySlope = 0.0;         // d(entry)/dQ
  std::vector<double> riseSlope;   // d(rise_j)/dQ
};

// The pressure changes at flow rate Q >= 0 through `channel` (open sections, at least two).
SectionDrops sectionDrops(const Channel &channel, const AirSettings &air, int throat, double Q);

}  // namespace glossa::airflow
