// Homogeneous uniaxial tension of an incompressible block through the full solve (Q1-P0,
// augmented Lagrangian to 1e-6) against the analytic stress-stretch relations, written here
// independently of the material code: with F = diag(lambda, lambda^-1/2, lambda^-1/2) and free
// lateral faces, P11 = (sigma_11 - sigma_22) / lambda where sigma_11 - sigma_22 is
//   neo-Hookean:  mu (lambda^2 - 1/lambda)
//   Fung:         2 A B exp(B (I1 - 3)) (lambda^2 - 1/lambda),  I1 = lambda^2 + 2/lambda
//   + fibres along x (eq. 6, one family, phi = 0.7): + phi lambda T0max 2 a A (lambda - 1) exp(a (lambda - 1)^2)
// The deformation is homogeneous, so the match is far closer than the 0.5 % a mesh study would need.
#include <array>
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {
const double A = 1652.0, B = 0.6265;                        // Table I muscle matrix
const double T0max = 668.8e3, a = 12.43, Ap = 8.568e-4, phi = 0.7; // Table I parallel element

double fungDifference(double l) {
  const double I1 = l * l + 2.0 / l;
  return 2.0 * A * B * std::exp(B * (I1 - 3.0)) * (l * l - 1.0 / l);
}

// The stretch at which P11(lambda) = t, by bisection on [lo, hi] (P11 increasing there).
double stretchFor(double t, const std::function<double(double)> &P11, double lo = 1.0, double hi = 3.0) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (P11(mid) < t ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void expectStretch(const std::vector<std::string> &overrides, double traction,
                   const std::function<double(double)> &P11, const std::string &tag) {
  auto all = overrides;
  all.push_back("Loads/pull/traction=" + std::to_string(traction) + ",0,0");
  const auto s = test::runDeck(test::inputPath("verification/uniaxial_tension.xml"), all,
                               test::scratchDirectory("uniaxial_" + tag));
  ASSERT_TRUE(s.at("converged").get<bool>()) << tag;
  const double L = 1e-3;
  const auto u = s.at("final_displacement").at("corner").get<std::vector<double>>();
  const double lambda = 1.0 + u[0] / L;
  const double exact = stretchFor(traction, P11);
  EXPECT_NEAR(lambda - 1.0, exact - 1.0, 1e-4 * (exact - 1.0)) << tag;
  // Incompressible: the lateral stretch is lambda^-1/2.
  EXPECT_NEAR(1.0 + u[1] / L, 1.0 / std::sqrt(exact), 1e-5) << tag;
  EXPECT_NEAR(u[1], u[2], 1e-15) << tag;
}
} // namespace

TEST(UniaxialTension, NeoHookean) {
  const double mu = 1000.0;
  expectStretch({"Material/type=neo-Hookean", "Material/shear modulus=1000"}, 1000.0,
                [&](double l) { return mu * (l * l - 1.0 / l) / l; }, "neo_hookean");
}

TEST(UniaxialTension, FungMuscleMatrix) {
  expectStretch({}, 1000.0, [](double l) { return fungDifference(l) / l; }, "fung");
}

TEST(UniaxialTension, PassiveFibreReinforcedMuscle) {
  auto P11 = [](double l) {
    const double Tp = T0max * 2.0 * a * Ap * (l - 1.0) * std::exp(a * (l - 1.0) * (l - 1.0));
    return (fungDifference(l) + phi * l * Tp) / l;
  };
  expectStretch({"Material/Fibre families/along x/direction=1,0,0"}, 2000.0, P11, "fibre");
}

// A probe (a named point inside an element, no node) gives the displacement interpolated in its
// element: the deformation being homogeneous, F X - X exactly, with lambda from the corner node.
// And the resultant on the loaded face set is the dead traction times the reference area, on the
// symmetry plane x = 0 the reaction of its condition.
TEST(UniaxialTension, ProbeAndFaceResultants) {
  const auto output = test::scratchDirectory("uniaxial_probe");
  const auto s = test::runDeck(test::inputPath("verification/uniaxial_tension.xml"),
                               {"Named points/inside/position=0.37e-3,0.61e-3,0.23e-3",
                                "Output/resultant face sets=xmax, xmin"},
                               output);
  ASSERT_TRUE(s.at("converged").get<bool>());
  const double L = 1e-3;
  const auto corner = s.at("final_displacement").at("corner").get<std::vector<double>>();
  const auto inside = s.at("final_displacement").at("inside").get<std::vector<double>>();
  const double axial = corner[0] / L, lateral = corner[1] / L; // lambda - 1, lambda^-1/2 - 1
  ASSERT_GT(axial, 0.05);
  EXPECT_NEAR(inside[0], axial * 0.37e-3, 1e-12);
  EXPECT_NEAR(inside[1], lateral * 0.61e-3, 1e-12);
  EXPECT_NEAR(inside[2], lateral * 0.23e-3, 1e-12);
  // resultants.csv, last row per face set.
  std::map<std::string, std::vector<double>> last;
  for (const auto &[name, rows] : test::readKeyedCsv(output / "resultants.csv")) last[name] = rows.back().values;
  const double load = 1000.0 * L * L; // P11 times the reference area of the x = 1 mm face
  EXPECT_NEAR(last.at("xmax")[0], load, 1e-9 * load);
  EXPECT_NEAR(last.at("xmin")[0], -load, 1e-6 * load);
  const auto reaction = s.at("steps").back().at("reactions").at("symmetry x").get<std::vector<double>>();
  EXPECT_NEAR(last.at("xmin")[0], reaction[0], 1e-12 * load);
}

// Compressed to lambda = 0.47 in one load step (mu = 1 kPa, P11 = -4 kPa, no cut-back allowed):
// Newton's first full step, lambda = 1 + P11 / (3 mu) = -1/3, turns the block inside out. With
// "full step" that fails the step; the guarded full step halves it until the state is valid and
// converges to the analytic stretch, mu (lambda - lambda^-2) = P11.
TEST(UniaxialTension, AnInvertingNewtonStepIsHalvedByTheGuardedFullStep) {
  const double mu = 1000.0, traction = -4000.0, L = 1e-3;
  const std::vector<std::string> oneStep = {"Material/type=neo-Hookean", "Material/shear modulus=1000",
                                            "Loads/pull/traction=-4000,0,0", "Time/step size=1",
                                            "Time/minimum step size=1"};
  auto with = [&](const std::string &lineSearch) {
    auto all = oneStep;
    all.push_back("Nonlinear solver/line search=" + lineSearch);
    std::string tag = lineSearch;
    for (char &c : tag) c = c == ' ' ? '_' : c;
    return test::runDeck(test::inputPath("verification/uniaxial_tension.xml"), all,
                         test::scratchDirectory("uniaxial_compressed_" + tag));
  };
  EXPECT_FALSE(with("full step").at("converged").get<bool>());
  const auto s = with("guarded full step");
  ASSERT_TRUE(s.at("converged").get<bool>());
  EXPECT_GE(s.at("newton_step_halvings").get<int>(), 1);
  const auto u = s.at("final_displacement").at("corner").get<std::vector<double>>();
  const double exact = stretchFor(
      traction, [&](double l) { return mu * (l - 1.0 / (l * l)); }, 0.1, 1.0);
  EXPECT_NEAR(exact, 0.4728, 1e-4);  // the root itself, as a check of the bracket
  EXPECT_NEAR(1.0 + u[0] / L, exact, 1e-4 * (1.0 - exact));
  EXPECT_NEAR(1.0 + u[1] / L, 1.0 / std::sqrt(exact), 1e-5);
}
