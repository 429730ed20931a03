// Follower pressure through the full solve (inputs/verification/thick_cylinder.xml): the
// inflation of a thick-walled incompressible neo-Hookean cylinder in plane strain against its
// closed form, integrated here independently of the solver (Ogden, Non-linear Elastic
// Deformations, §5.3): with c = a^2 - A^2, r^2 = R^2 + c and lambda = r / R,
//   p(a) = mu int_a^b (lambda^2 - lambda^-2) dr / r,   b^2 = B^2 + c.
// The deformed inner radius matches within 0.5 % at 8 x 16 cells (1 % would do), the error
// falls by about 4x per refinement, and Newton stays quadratic with the non-symmetric tangent.
#include <cmath>

#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {
const double A = 1e-3, B = 2e-3, mu = 1e4, p = 3000.0;

double pressureAt(double a) {
  const double c = a * a - A * A, b = std::sqrt(B * B + c);
  const int n = 2000; // Simpson's rule
  auto f = [&](double r) {
    const double l2 = r * r / (r * r - c);
    return (l2 - 1.0 / l2) / r;
  };
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(a + (b - a) * i / n);
  return mu * s * (b - a) / (3.0 * n);
}

double exactInnerRadius() {
  double lo = A, hi = 1.5 * A;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (pressureAt(mid) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double innerDisplacement(const std::string &cells, nlohmann::json *summary = nullptr) {
  const auto s = test::runDeck(test::inputPath("verification/thick_cylinder.xml"),
                               {"Mesh/Thick cylinder/cells=" + cells}, test::scratchDirectory("cylinder_" + cells));
  EXPECT_TRUE(s.at("converged").get<bool>());
  if (summary) *summary = s;
  return s.at("final_displacement").at("inner").get<std::vector<double>>()[0];
}
} // namespace

TEST(FollowerPressure, ThickCylinderInflationMatchesTheClosedForm) {
  const double exact = exactInnerRadius() - A;
  nlohmann::json s;
  const double coarse = innerDisplacement("4,8,1"), medium = innerDisplacement("8,16,1", &s);
  EXPECT_NEAR(medium, exact, 5e-3 * exact);
  const double ratio = std::abs(coarse - exact) / std::abs(medium - exact);
  EXPECT_GT(ratio, 3.0) << "coarse " << coarse << " medium " << medium << " exact " << exact;
  // Quadratic Newton with the follower tangent, above round-off (2e-12 of |f_0| here): pairs down
  // to 1e-11 of it count (the steps' few iterations leave 4 pairs above 1e-10).
  EXPECT_GE(test::expectQuadraticNewton(s, 1e-11), 5);
}
