// The augmented Lagrangian reaches a dilatation error below 0.1 % with kappa_AL/mu = 100, where a
// pure penalty with the same kappa in the tangent does not; the multiplier converges to the
// pressure of the deck's physical law (nu = 0.4999), so the displacement matches that reference.
#include <cmath>

#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {
double maxDilatationError(const nlohmann::json &summary) {
  double e = 0.0;
  for (const auto &s : summary.at("steps")) e = std::max(e, s.at("max_dilatation_error").get<double>());
  return e;
}
} // namespace

TEST(AugmentedLagrangian, Step44BlockReachesTheDilatationTolerance) {
  const std::vector<std::string> common = {"Mesh/Box/cells=8,8,8", "Incompressibility/penalty ratio=100"};
  auto al = common;
  al.push_back("Incompressibility/method=augmented Lagrangian");
  const auto withUzawa = test::runDeck(test::inputPath("verification/step44_block.xml"), al,
                                       test::scratchDirectory("al_step44"));
  ASSERT_TRUE(withUzawa.at("converged").get<bool>());
  EXPECT_LT(maxDilatationError(withUzawa), 1e-3);
  for (const auto &s : withUzawa.at("steps")) {
    EXPECT_GE(s.at("uzawa_iterations").get<int>(), 2) << "the first solve alone is not incompressible enough";
    EXPECT_GT(s.at("linear_iterations").get<int>(), 0);
  }
  EXPECT_NEAR(withUzawa.at("kappa_AL_over_mu").get<double>(), 100.0, 1e-9);
  // nu = 0.4999 gives kappa/mu = 2 (1.4999) / (3 x 0.0002) = 4999.67; the tangent has the series modulus.
  const double kappa = 2.0 * 1.4999 / (3.0 * 0.0002);
  EXPECT_NEAR(withUzawa.at("kappa_over_mu").get<double>(), kappa * 100.0 / (kappa + 100.0), 1e-9);

  // The same kappa as a pure penalty: one solve per step and a dilatation error far above 0.1 %.
  auto penalty = common;
  penalty.push_back("Material/bulk modulus=8.0194e9");
  const auto withoutUzawa = test::runDeck(test::inputPath("verification/step44_block.xml"), penalty,
                                          test::scratchDirectory("penalty_step44"));
  ASSERT_TRUE(withoutUzawa.at("converged").get<bool>());
  EXPECT_GT(maxDilatationError(withoutUzawa), 3e-3);

  // With the multiplier the top-face centre moves as in the nu = 0.4999 reference (deal.II,
  // 8 per side: -0.777613 mm) to within the effect of the remaining dilatation.
  const double uy = withUzawa.at("final_displacement").at("top_centre").at(1).get<double>();
  EXPECT_NEAR(uy, -0.777613e-3, 1e-3 * 0.777613e-3);
}

TEST(AugmentedLagrangian, CookMembraneReachesTheDilatationTolerance) {
  const auto summary = test::runDeck(test::inputPath("verification/cook_membrane.xml"),
                                     {"Incompressibility/method=augmented Lagrangian"},
                                     test::scratchDirectory("al_cook"));
  ASSERT_TRUE(summary.at("converged").get<bool>());
  EXPECT_LT(maxDilatationError(summary), 1e-3);
}
