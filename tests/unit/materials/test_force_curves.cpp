#include <gtest/gtest.h>

#include <cmath>

#include "materials/ContractileCurveSets.hpp"
#include "materials/GaussMollifierCurve.hpp"

using namespace glossa::materials;

namespace {
double fL(const ContractileCurves &c, double x) { return c.forceLength->evaluate(x).value; }
double fV(const ContractileCurves &c, double x) { return c.forceVelocity->evaluate(x).value; }

// The targets of materials/fit/fit_physiological_curves.py (doc/materials.md).
double gordonHuxleyJulian(double lambda) {
  const double x[] = {1.27 / 2.125, 1.67 / 2.125, 2.0 / 2.125, 2.25 / 2.125, 3.65 / 2.125};
  const double y[] = {0.0, 0.84, 1.0, 1.0, 0.0};
  if (lambda <= x[0] || lambda >= x[4]) return 0.0;
  int i = 0;
  while (lambda > x[i + 1]) ++i;
  return y[i] + (y[i + 1] - y[i]) * (lambda - x[i]) / (x[i + 1] - x[i]);
}
double hillAndVanSoest(double v) {
  return v <= 0.0 ? (1.0 + v / 10.0) / (1.0 - v / 2.5) : 1.5 - 0.25 / (v + 0.5);
}
}  // namespace

// Values computed by hand from Table II with g = A exp(-B|x-mu|^p) (R^q - |x-mu|^q)^s.
TEST(PaperTableII, ForceLengthAtHandComputedPoints) {
  const ContractileCurves c = paperTableIICurves();
  // lambda_c = 0.8: d = 0, -0.5, -0.525 for the three terms.
  const double at08 = 0.475 + 0.1 * std::exp(-10 * 0.25) * std::pow(1 - 0.25, 8) +
                      4830.635 * std::exp(-3 * 0.525) * std::pow(std::pow(0.75, 4) - std::pow(0.525, 4), 8);
  EXPECT_NEAR(fL(c, 0.8), at08, 1e-14);
  EXPECT_NEAR(fL(c, 0.8), 0.48699, 1e-5);  // doc/materials.md: 0.49 at 0.8
  // lambda_c = 1: d = 0.2, -0.3, -0.325.
  const double at1 = 0.475 * std::exp(-90 * 0.04) * std::pow(1 - 0.0016, 8) +
                     0.1 * std::exp(-10 * 0.09) * std::pow(1 - 0.09, 8) +
                     4830.635 * std::exp(-3 * 0.325) * std::pow(std::pow(0.75, 4) - std::pow(0.325, 4), 8);
  EXPECT_NEAR(fL(c, 1.0), at1, 1e-14);
  EXPECT_NEAR(fL(c, 1.0), 0.169, 1e-3);  // doc/materials.md: only 0.17 at lambda_c = 1
  // The cusp of term 3 (p = 1) at 1.325: 4830.635 * 0.75^32 = 0.485 plus term 2.
  EXPECT_NEAR(fL(c, 1.325),
              4830.635 * std::pow(0.75, 32) +
                  0.1 * std::exp(-10 * 0.025 * 0.025) * std::pow(1 - 0.025 * 0.025, 8) +
                  0.475 * std::exp(-90 * 0.525 * 0.525) * std::pow(1 - std::pow(0.525, 4), 8),
              1e-14);
  EXPECT_NEAR(fL(c, 1.325), 0.58, 5e-3);
  // Outside [0.5, 2]: zero (eq. 19).
  EXPECT_EQ(fL(c, 0.4999), 0.0);
  EXPECT_EQ(fL(c, 2.0001), 0.0);
}

TEST(PaperTableII, ForceVelocityAtHandComputedPoints) {
  const ContractileCurves c = paperTableIICurves();
  const double at0 = 2.5e-5 * std::exp(-0.01 * 0.5625) * std::pow(100 - 0.5625, 2) +
                     0.3 * std::exp(-0.25 * 0.36) + 0.425 * std::exp(-0.7 * 0.3025) +
                     0.1 * std::exp(-0.3 * std::pow(1.4, 4)) + 0.525 * std::exp(-15 * std::pow(0.75, 8));
  EXPECT_NEAR(fV(c, 0.0), at0, 1e-14);
  EXPECT_NEAR(fV(c, 0.0), 1.01, 5e-3);  // doc/materials.md: f_cV(0) = 1.01
  // Term 1's peak 2.5e-5 * 10^4 = 0.25 (the printed "2.5105" is 2.5e-5).
  EXPECT_NEAR(2.5e-5 * std::pow(10.0, 4), 0.25, 1e-15);
  // Rises to 1.49 near 0.47 and falls back to ~0 by 3 (doc/materials.md).
  EXPECT_NEAR(fV(c, 0.47), 1.492, 1e-3);
  EXPECT_LT(fV(c, 3.0), 0.2);
  EXPECT_LT(fV(c, 9.9), 1e-10);
  // Eq. 20's branches.
  EXPECT_EQ(fV(c, -10.001), 0.0);
  EXPECT_EQ(fV(c, 10.001), 1.5);
}

TEST(ContractileCurves, SlopesMatchFiniteDifferences) {
  for (const ContractileCurves &c : {paperTableIICurves(), physiologicalCurves()}) {
    for (double x = 0.52; x < 1.99; x += 0.0371) {
      if (std::abs(x - 1.325) < 1e-3) continue;  // the paper set's cusp (p = 1)
      const double h = 1e-6;
      const double fd = (fL(c, x + h) - fL(c, x - h)) / (2 * h);
      EXPECT_NEAR(c.forceLength->evaluate(x).slope, fd, 1e-6 * (1 + std::abs(fd))) << x;
    }
    for (double v = -9.97; v < 9.99; v += 0.2371) {
      const double h = 1e-6;
      const double fd = (fV(c, v + h) - fV(c, v - h)) / (2 * h);
      EXPECT_NEAR(c.forceVelocity->evaluate(v).slope, fd, 1e-6 * (1 + std::abs(fd))) << v;
    }
  }
}

// Every curve against eq. 21 written out with std::pow and its derivative by hand, term by term,
// at points across both domains: the evaluation's shortcuts (integer power chains, the p = q = 2
// terms without them) change no more than round-off.
TEST(ContractileCurves, EvaluationMatchesTheFormulaWrittenOut) {
  auto formula = [](const GaussMollifierCurve &c, double x, double &slope) {
    double value = 0.0;
    slope = 0.0;
    for (const GaussMollifierTerm &t : c.terms()) {
      const double d = x - t.mu, ad = std::abs(d), sign = d > 0.0 ? 1.0 : (d < 0.0 ? -1.0 : 0.0);
      if (t.R > 0.0 && ad >= t.R) continue;
      const double G = t.A * std::exp(-t.B * std::pow(ad, t.p));
      const double dG = -G * t.B * t.p * std::pow(ad, t.p - 1.0) * sign;
      const double M = t.R > 0.0 ? std::pow(std::pow(t.R, t.q) - std::pow(ad, t.q), t.s) : 1.0;
      const double dM = t.R > 0.0 ? -t.s * t.q * std::pow(std::pow(t.R, t.q) - std::pow(ad, t.q), t.s - 1.0) *
                                        std::pow(ad, t.q - 1.0) * sign
                                  : 0.0;
      value += G * M;
      slope += dG * M + G * dM;
    }
    return value;
  };
  int compared = 0;
  for (const ContractileCurves &c : {paperTableIICurves(), physiologicalCurves()})
    for (const auto &curve : {c.forceLength, c.forceVelocity}) {
      const auto &g = dynamic_cast<const GaussMollifierCurve &>(*curve);
      for (double x = g.lower() + 0.013; x < g.upper(); x += (g.upper() - g.lower()) / 97.0) {
        double slope = 0.0;
        const double value = formula(g, x, slope);
        const CurveValue v = g.evaluate(x);
        const double scale = std::abs(value) + 1e-3;
        EXPECT_NEAR(v.value, value, 1e-13 * scale) << x;
        EXPECT_NEAR(v.slope, slope, 1e-12 * (std::abs(slope) + 1e-3)) << x;
        ++compared;
      }
    }
  EXPECT_GT(compared, 350);
}

TEST(ContractileCurves, UpperBoundsHold) {
  for (const ContractileCurves &c : {paperTableIICurves(), physiologicalCurves()}) {
    double maxL = 0, maxV = 0;
    for (double x = 0.0; x < 2.5; x += 1e-4) maxL = std::max(maxL, fL(c, x));
    for (double v = -12; v < 12; v += 1e-3) maxV = std::max(maxV, fV(c, v));
    EXPECT_LE(maxL, c.forceLength->upperBound());
    EXPECT_LE(maxV, c.forceVelocity->upperBound());
    EXPECT_EQ(c.forceVelocity->zeroBelow(), -10.0);
    EXPECT_EQ(c.forceLength->zeroBelow(), 0.5);
  }
}

// The physiological set: f_cL peaks at 1 with value 1 and vanishes outside [0.5, 2] continuously;
// f_cV = 1 at 0, 0 at -10, 1.5 at +10 (C1 join), rising monotonically; both within the fit's
// recorded residual of their targets.
TEST(Physiological, ForceLengthShape) {
  const ContractileCurves c = physiologicalCurves();
  EXPECT_NEAR(fL(c, 1.0), 1.0, 1e-14);
  EXPECT_NEAR(c.forceLength->evaluate(1.0).slope, 0.0, 1e-4);
  double maxValue = 0, argMax = 0, maxResidual = 0;
  for (double x = 0.5; x <= 2.0; x += 1e-5) {
    const double f = fL(c, x);
    if (f > maxValue) maxValue = f, argMax = x;
    maxResidual = std::max(maxResidual, std::abs(f - gordonHuxleyJulian(x)));
    EXPECT_GE(f, 0.0);
  }
  EXPECT_LE(maxValue, 1.0 + 1e-9);
  EXPECT_NEAR(argMax, 1.0, 1e-4);
  EXPECT_LT(maxResidual, 0.055);  // fit report: max |residual| 0.054 at the GHJ corner 0.598
  EXPECT_LT(fL(c, 0.5 + 1e-4), 1e-6);
  EXPECT_EQ(fL(c, 0.5), 0.0);
  EXPECT_EQ(fL(c, 1.9), 0.0);
  EXPECT_EQ(fL(c, 0.45), 0.0);
  EXPECT_EQ(fL(c, 2.1), 0.0);
  EXPECT_GT(fL(c, 0.8), 0.8);
  EXPECT_GT(fL(c, 1.2), 0.75);
}

TEST(Physiological, ForceVelocityShape) {
  const ContractileCurves c = physiologicalCurves();
  EXPECT_NEAR(fV(c, 0.0), 1.0, 1e-14);
  EXPECT_NEAR(fV(c, -10.0), 0.0, 1e-15);
  EXPECT_NEAR(fV(c, 10.0), 1.5, 1e-14);
  EXPECT_NEAR(c.forceVelocity->evaluate(10.0).slope, 0.0, 1e-14);
  EXPECT_EQ(fV(c, 10.5), 1.5);
  EXPECT_EQ(fV(c, -10.5), 0.0);
  double previous = -1, maxResidual = 0;
  for (double v = -10.0; v <= 10.0; v += 1e-4) {
    const double f = fV(c, v);
    EXPECT_GE(f, previous) << v;
    previous = f;
    maxResidual = std::max(maxResidual, std::abs(f - hillAndVanSoest(v)));
  }
  EXPECT_LT(maxResidual, 0.061);  // fit report: max |residual| 0.0605 near the kink at v = 0
  EXPECT_GT(c.forceVelocity->evaluate(-9.99).slope, 0.0);  // closes with non-zero slope like Hill
}

TEST(ContractileCurves, SelectionByName) {
  EXPECT_EQ(fL(contractileCurvesFromName("paper-table-II"), 0.8), fL(paperTableIICurves(), 0.8));
  EXPECT_EQ(fL(contractileCurvesFromName("physiological"), 0.8), fL(physiologicalCurves(), 0.8));
  EXPECT_EQ(std::string(defaultContractileCurveSet()), "physiological");
  EXPECT_THROW(contractileCurvesFromName("paper"), std::invalid_argument);
  EXPECT_THROW(GaussMollifierCurve({{0, 2, 1, 1, 1, 0, 0}}, 0, 1, 0, 0), std::invalid_argument);
  EXPECT_THROW(GaussMollifierCurve({}, 1, 0, 0, 0), std::invalid_argument);
}
