// The material's Poisson's ratio is the physical law also under the augmented Lagrangian: at
// nu = 0.4999 the Uzawa loop reaches the displacement of the one-solve penalty with that bulk
// modulus, and nu = 0.5 (exact incompressibility) reaches theta = 1 and the limit the penalty
// solutions approach as kappa -> inf (extrapolated from nu = 0.4999 and 0.49999 as u = u_inf + c/kappa).
#include <gtest/gtest.h>

#include <cmath>

#include "RunDeck.hpp"
#include "io/deck/DeckError.hpp"

using namespace glossa;

namespace {
const std::string kDeck = "verification/step44_block.xml";

double topCentre(const nlohmann::json &s) {
  return s.at("final_displacement").at("top_centre").at(1).get<double>();
}

double maxOver(const nlohmann::json &s, const std::string &key) {
  double e = 0.0;
  for (const auto &step : s.at("steps")) e = std::max(e, step.at(key).get<double>());
  return e;
}

double kappaOverMu(double nu) { return 2.0 * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu)); }

// 4 elements per side, a direct linear solve and tight Newton tolerances, so that what differs
// between the runs is the incompressibility treatment alone.
std::vector<std::string> common(const std::string &nu) {
  return {"Mesh/Box/cells=4,4,4",
          "Linear solver/type=direct",
          "Nonlinear solver/residual tolerance=1e-10",
          "Nonlinear solver/update tolerance=1e-10",
          "Output/fields=false",
          "Material/Poisson's ratio=" + nu};
}

nlohmann::json run(std::vector<std::string> overrides, const std::vector<std::string> &more,
                   const std::string &dir) {
  overrides.insert(overrides.end(), more.begin(), more.end());
  auto s = test::runDeck(test::inputPath(kDeck), overrides, test::scratchDirectory(dir));
  EXPECT_TRUE(s.at("converged").get<bool>()) << dir;
  return s;
}
}  // namespace

TEST(PhysicalKappa, AugmentedLagrangianAtNu04999MatchesThePenaltySolve) {
  const auto penalty = run(common("0.4999"), {"Incompressibility/method=penalty"}, "kappa_penalty");
  const auto al =
      run(common("0.4999"),
          {"Incompressibility/method=augmented Lagrangian", "Incompressibility/dilatation tolerance=1e-10"},
          "kappa_al");
  EXPECT_NEAR(topCentre(al), topCentre(penalty), 1e-6 * std::abs(topCentre(penalty)));
  EXPECT_LT(maxOver(al, "max_dilatation_error"), 1e-10);
  // The law's own volume change is kept (p / kappa ~ 1e-3 under the 400 MPa patch), not removed.
  EXPECT_NEAR(maxOver(al, "max_volume_change"), maxOver(penalty, "max_volume_change"),
              1e-4 * maxOver(penalty, "max_volume_change"));
  EXPECT_GT(maxOver(al, "max_volume_change"), 1e-4);
  EXPECT_GE(al.at("steps").at(0).at("uzawa_iterations").get<int>(), 2);
}

TEST(PhysicalKappa, NuOneHalfIsExactlyIncompressibleAndTheLimitOfThePenalty) {
  const auto exact = run(common("0.5"), {"Incompressibility/method=augmented Lagrangian"}, "kappa_exact");
  EXPECT_LT(maxOver(exact, "max_dilatation_error"), 1e-3);  // the default tolerance
  EXPECT_LT(maxOver(exact, "max_volume_change"), 1e-3);     // which for nu = 0.5 is |theta - 1|
  EXPECT_EQ(exact.at("kappa_AL_over_mu").get<double>(), 30.0); // the default penalty ratio
  EXPECT_NEAR(exact.at("kappa_over_mu").get<double>(), 30.0, 1e-12);

  const auto tight =
      run(common("0.5"),
          {"Incompressibility/method=augmented Lagrangian", "Incompressibility/dilatation tolerance=1e-9"},
          "kappa_exact_tight");
  EXPECT_LT(maxOver(tight, "max_volume_change"), 1e-9);
  const auto p1 = run(common("0.4999"), {"Incompressibility/method=penalty"}, "kappa_p1");
  const auto p2 = run(common("0.49999"), {"Incompressibility/method=penalty"}, "kappa_p2");
  const double k1 = kappaOverMu(0.4999), k2 = kappaOverMu(0.49999);
  const double uInf = (k2 * topCentre(p2) - k1 * topCentre(p1)) / (k2 - k1);
  // The extrapolation removes the 1/kappa term; what is left is O(1/kappa^2) ~ 1e-8 relative.
  EXPECT_NEAR(topCentre(tight), uInf, 1e-6 * std::abs(uInf));
  EXPECT_GT(std::abs(topCentre(p1) - uInf), 1e-5 * std::abs(uInf)) << "nu = 0.4999 must differ measurably";
}

TEST(PhysicalKappa, APenaltyCannotExpressNuOneHalf) {
  EXPECT_THROW(test::runDeck(test::inputPath(kDeck), common("0.5"), test::scratchDirectory("kappa_refused")),
               io::DeckError);
}
