#include "airflow/SectionMarch.hpp"

#include <cmath>

namespace glossa::airflow {

int throatOf(const Channel &channel) {
  int m = 0;
  for (int i = 1; i < static_cast<int>(channel.size()); ++i)
    if (channel[i].area < channel[m].area) m = i;
  return m;
}

SectionDrops sectionDrops(const Channel &channel, const AirSettings &air, int throat, double Q) {
  const int n = static_cast<int>(channel.size());
  const double halfRho = 0.5 * air.density;
  auto inverseSquare = [&](int i) { return 1.0 / (channel[i].area * channel[i].area); };
  SectionDrops d;
  d.entry = halfRho * Q * Q * inverseSquare(0);
  d.entrySlope = 2.0 * halfRho * Q * inverseSquare(0);
  d.rise.resize(n - 1);
  d.riseSlope.resize(n - 1);
  for (int j = 0; j + 1 < n; ++j) {
    const double c = j < throat ? 1.0 : air.recoveryCoefficient;
    const double dynamic = c * halfRho * (inverseSquare(j) - inverseSquare(j + 1));
    // Hagen-Poiseuille, dp/ds = -8 mu Q / (pi R^4) with pi R^2 = A: -8 pi mu Q / A^2.
    const double length = channel[j + 1].arcLength - channel[j].arcLength;
    const double viscous = 4.0 * M_PI * air.viscosity * length * (inverseSquare(j) + inverseSquare(j + 1));
    d.rise[j] = dynamic * Q * Q - viscous * Q;
    d.riseSlope[j] = 2.0 * dynamic * Q - viscous;
  }
  return d;
}

}  // namespace glossa::airflow
