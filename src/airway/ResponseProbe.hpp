#pragma once
// Probing the lumen along a linearised response du (the displacement per unit of a load or an
// input): the lumen is measured at u + h du with h scaled so that the node du moves most moves
// by kProbeDisplacement, small against the lumen (millimetres) and its mesh, large against
// round-off in its areas. The airflow coupling's Jacobian (solvers/run/AirflowCoupling) and the
// controller's airway sensitivity (solvers/run/ControlledSteps) difference the lumen so.

#include <algorithm>
#include <cmath>
#include <vector>

namespace glossa::airway {

constexpr double kProbeDisplacement = 1e-6; // [m]

// h = kProbeDisplacement / max |du|, in du's inverse units; 0 when du is zero everywhere.
inline double probeStep(const std::vector<double> &du) {
  double largest = 0.0;
  for (const double d : du) largest = std::max(largest, std::abs(d));
  return largest > 0.0 ? kProbeDisplacement / largest : 0.0;
}

// u + h du.
inline std::vector<double> probed(const std::vector<double> &u, const std::vector<double> &du, double h) {
  std::vector<double> x(u);
  for (std::size_t k = 0; k < x.size() && k < du.size(); ++k) x[k] += h * du[k];
  return x;
}

}  // namespace glossa::airway
