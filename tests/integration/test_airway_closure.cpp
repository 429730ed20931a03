// Closure in a known case (doc/airway.md, "Pcrit"): inputs/verification/airway_closing_block.xml,
// a block in uniaxial strain F = diag(1, 1, lambda) whose top a ramped suction draws towards a
// rigid wall 0.1 mm above it. The lumen closes when the top's gap to the wall falls to what
// closes a section: 0 (contact across the whole 4 mm width) with 'closing area' 0, or
// area / width with a closing area. The suction then equals the Cauchy stress of uniaxial strain,
// written here independently of the material code:
//   sigma_zz = (2 mu / 3) lambda^(-5/3) (lambda^2 - 1) + (kappa / 2) (lambda - 1 / lambda),
// lambda = 1 + (0.1 mm - closing gap) / 2 mm. The run's bisected bracket must hold it and be at
// most the deck's 1 Pa wide; the open end's top must stand just short of the closing gap.
#include <cmath>

#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {
const double mu = 1e4, kappa = 2e4, H = 2e-3, g0 = 1e-4, width = 4e-3;

double sigmaZZ(double lambda) {
  return 2.0 * mu / 3.0 * std::pow(lambda, -5.0 / 3.0) * (lambda * lambda - 1.0) +
         0.5 * kappa * (lambda - 1.0 / lambda);
}

void expectClosingPressure(const std::string &closingAreaText, const std::string &tag) {
  const double closingArea = std::stod(closingAreaText);
  const auto s = test::runDeck(test::inputPath("verification/airway_closing_block.xml"),
                               {"Airway/closing area=" + closingAreaText},
                               test::scratchDirectory("airway_closing_block_" + tag));
  ASSERT_TRUE(s.at("converged").get<bool>()) << tag;
  const auto &p = s.at("pcrit");
  ASSERT_TRUE(p.at("closed").get<bool>()) << tag;
  ASSERT_TRUE(p.at("bracketed").get<bool>()) << tag;
  const double closingGap = closingArea / width;
  const double exact = -sigmaZZ(1.0 + (g0 - closingGap) / H);
  const double lo = p.at("low_Pa"), hi = p.at("high_Pa");
  EXPECT_LE(hi - lo, 1.0) << tag;
  EXPECT_LE(lo, exact) << tag;
  EXPECT_GE(hi, exact) << tag;
  EXPECT_NEAR(p.at("cmH2O").get<double>(), p.at("Pa").get<double>() / 98.0665, 1e-12) << tag;
  // The run ends at the bracket's open end: the top short of closing, by less than the 1 Pa
  // bracket moves it (d sigma / d lambda is about 2e4 Pa, so 1 Pa is 0.1 um of the 2 mm height).
  const double uTop = s.at("final_displacement").at("top centre")[2];
  EXPECT_LT(uTop, g0 - closingGap) << tag;
  EXPECT_GT(uTop, g0 - closingGap - 2e-7) << tag;
}
} // namespace

TEST(AirwayClosure, ContactAcrossTheWidthAtTheUniaxialStrainSuction) { expectClosingPressure("0", "contact"); }

TEST(AirwayClosure, ClosingAreaAtTheUniaxialStrainSuction) {
  // 0.2 mm^2 over the 4 mm width: closed at a gap of 0.05 mm, before any contact.
  expectClosingPressure("2e-7", "area");
}
