#include "fem/DiscreteGradient.hpp"

#include <cmath>
#include <limits>

namespace glossa::fem {

namespace {

// du without its mean nodal translation (dof 3 a + i).
ElementVector withoutTranslation(const ElementVector &du) {
  ElementVector d = du;
  for (int i = 0; i < 3; ++i) {
    double mean = 0.0;
    for (int a = 0; a < 8; ++a) mean += du(3 * a + i);
    mean /= 8.0;
    for (int a = 0; a < 8; ++a) d(3 * a + i) -= mean;
  }
  return d;
}

} // namespace

DiscreteGradientCorrection discreteGradientCorrection(const ElementVector &du, double W0, double W1,
                                                      const ElementVector &meanForce) {
  DiscreteGradientCorrection out;
  const double work = meanForce.dot(du);
  const double error = (W1 - W0) - work;
  // The energies' difference carries their round-off: below it there is nothing to correct, and
  // dividing it by a small |d|^2 would only amplify noise.
  const double floor = 64.0 * std::numeric_limits<double>::epsilon() * (std::abs(W0) + std::abs(W1) + std::abs(work));
  if (!(std::abs(error) > floor)) return out;
  const ElementVector d = withoutTranslation(du);
  const double dd = d.squaredNorm();
  if (!(dd > 0.0)) return out;
  out.coefficient = error / dd;
  out.force = out.coefficient * d;
  return out;
}

void addTranslationFreeIdentity(ElementMatrix &K, double c) {
  if (c == 0.0) return;
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      const double pab = (a == b ? 1.0 : 0.0) - 1.0 / 8.0;
      for (int i = 0; i < 3; ++i) K(3 * a + i, 3 * b + i) += c * pab;
    }
}

} // namespace glossa::fem
