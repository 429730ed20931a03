// Two tissues in one mesh (inputs/verification/two_tissues.xml): a bar whose halves have their
// own matrix law, bulk modulus and density (Material and Material/Tissues/stiff), in uniaxial
// strain. Against the closed form, written here from the energy independently of the solver:
// each half is homogeneous, F = diag(lambda_i, 1, 1), J = lambda_i, and carries the end traction
//   P = 2 mu_i / 3 (lambda_i^(1/3) - lambda_i^(-5/3)) + kappa_i / 2 (lambda_i - 1 / lambda_i)
// (neo-Hookean isochoric part, U = kappa/4 (theta^2 - 1 - 2 ln theta)). Under a body force alone
// the support carries the weight of both tissues, each with its own density (conservation).
#include <cmath>

#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {
double traction(double lambda, double mu, double kappa) {
  return 2.0 * mu / 3.0 * (std::cbrt(lambda) - std::pow(lambda, -5.0 / 3.0)) + 0.5 * kappa * (lambda - 1.0 / lambda);
}

// The stretch carrying P, by bisection on [1, 3] (P rises monotonically with lambda).
double stretchFor(double P, double mu, double kappa) {
  double lo = 1.0, hi = 3.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (traction(mid, mu, kappa) < P ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}
} // namespace

TEST(TwoTissues, InSeriesMatchTheClosedForm) {
  const auto s = test::runDeck(test::inputPath("verification/two_tissues.xml"), {}, test::scratchDirectory("two_tissues"));
  ASSERT_TRUE(s.at("converged").get<bool>());
  const double soft = stretchFor(1000.0, 1000.0, 5000.0), stiff = stretchFor(1000.0, 4000.0, 20000.0);
  ASSERT_GT(soft - 1.0, 3.0 * (stiff - 1.0)); // the two halves really differ
  const auto &u = s.at("final_displacement");
  const double interface = u.at("interface").get<std::vector<double>>()[0];
  const double end = u.at("end").get<std::vector<double>>()[0];
  EXPECT_NEAR(interface, soft - 1.0, 1e-8);
  EXPECT_NEAR(end - interface, stiff - 1.0, 1e-8);
  EXPECT_NEAR(u.at("end").get<std::vector<double>>()[1], 0.0, 1e-14);
  // The summary lists both tissues with their elements.
  const auto &tissues = s.at("tissues");
  ASSERT_EQ(tissues.size(), 2u);
  EXPECT_EQ(tissues[0].at("name"), "Material");
  EXPECT_EQ(tissues[1].at("name"), "stiff");
  EXPECT_EQ(tissues[0].at("elements").get<int>(), 4);
  EXPECT_EQ(tissues[1].at("elements").get<int>(), 4);
  EXPECT_EQ(tissues[1].at("density").get<double>(), 1900.0);
}

TEST(TwoTissues, TheSupportCarriesTheWeightOfEachTissue) {
  const double a = 0.1; // m/s^2 along +x, away from the support at x = 0
  const auto s = test::runDeck(test::inputPath("verification/two_tissues.xml"),
                               {"Loads/pull/type=body force", "Loads/pull/acceleration=0.1,0,0", "Loads/pull/traction=0,0,0",
                                // the residual 100x below the balance asked of the reaction
                                "Nonlinear solver/residual tolerance=1e-11"},
                               test::scratchDirectory("two_tissues_weight"));
  ASSERT_TRUE(s.at("converged").get<bool>());
  const double weight = a * (920.0 * 1.0 + 1900.0 * 1.0); // rho_i V_i of each half
  const auto reaction = s.at("steps").back().at("reactions").at("end x").get<std::vector<double>>();
  EXPECT_NEAR(reaction[0], -weight, 1e-9 * weight);
}
