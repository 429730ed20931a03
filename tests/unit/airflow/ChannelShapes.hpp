#pragma once
// Rigid channels whose 1/A^2 is piecewise linear in the arc length, so that the viscous loss
// 8 pi mu Q integral(1/A^2 ds) has a closed form, and the quadratic the pressure drop solves.

#include <cmath>
#include <vector>

#include "airflow/FlowChannel.hpp"

namespace glossa::airflow::test {

constexpr double kRho = 1.2, kMu = 1.8e-5;

// 1/A^2 falls linearly from the throat's gThroat at sThroat to gStart at s = 0 and to gEnd at
// s = length; `sections` equally spaced sections, one of them at sThroat.
struct PeakedChannel {
  double gStart, gThroat, gEnd, sThroat, length;
  int sections;

  double inverseSquareArea(double s) const {
    return s <= sThroat ? gStart + (gThroat - gStart) * s / sThroat
                        : gThroat + (gEnd - gThroat) * (s - sThroat) / (length - sThroat);
  }
  Channel channel() const {
    Channel c(sections);
    for (int i = 0; i < sections; ++i) {
      c[i].arcLength = length * i / (sections - 1);
      c[i].area = 1.0 / std::sqrt(inverseSquareArea(c[i].arcLength));
    }
    return c;
  }
  // The exact integral of 1/A^2 over the channel.
  double integralOfInverseSquareArea() const {
    return 0.5 * (gStart + gThroat) * sThroat + 0.5 * (gThroat + gEnd) * (length - sThroat);
  }
};

// The positive root of a Q^2 + b Q = dp (a > 0 or b > 0), in the form without cancellation.
inline double positiveRoot(double a, double b, double dp) { return 2.0 * dp / (b + std::sqrt(b * b + 4.0 * a * dp)); }

}  // namespace glossa::airflow::test
