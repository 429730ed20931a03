// The contact patch test through the full solve (inputs/verification/contact_patch_block.xml): a
// block pressed onto a rigid plane by a uniform follower pressure p on its top is in homogeneous
// uniaxial compression, so the plane must carry p uniformly. With the penalty method the contact
// pressure at a point is eps times its penetration: every traced bottom node (the origin, an edge,
// an inner node, the far corner) sinks by p / eps to 1e-6, and the bottom's resultant (the force
// the plane exerts) equals the applied load, p times the deformed top area, to 1e-6. Both contact
// point rules pass on the box's rectangular faces (doc/contact.md).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {
const double p = 1e3, eps = 1e10, L = 1e-3;

void expectUniformContactPressure(const std::string &rule) {
  const auto output = test::scratchDirectory("contact_patch_" + rule);
  const auto s = test::runDeck(test::inputPath("verification/contact_patch_block.xml"),
                               {"Contact/floor/contact points=" + rule}, output);
  ASSERT_TRUE(s.at("converged").get<bool>());
  const auto &u = s.at("final_displacement");
  for (const char *point : {"origin", "bottom edge", "bottom inner", "bottom corner"}) {
    const double pressure = -eps * u.at(point).get<std::vector<double>>()[2];
    EXPECT_NEAR(pressure, p, 1e-6 * p) << rule << ": " << point;
  }
  // The block has spread sideways (nu = 0.3): the load is p times the deformed top area.
  const auto top = u.at("top corner").get<std::vector<double>>();
  ASSERT_GT(top[0], 1e-3 * L);
  ASSERT_LT(top[2], -1e-2 * L);
  const double load = p * (L + top[0]) * (L + top[1]);
  const auto resultants = test::readKeyedCsv(output / "resultants.csv");
  const auto &bottom = resultants.at("zmin").back().values;
  EXPECT_NEAR(bottom[2], load, 1e-6 * load) << rule;
  EXPECT_NEAR(bottom[0], 0.0, 1e-9 * load) << rule;
  EXPECT_NEAR(bottom[1], 0.0, 1e-9 * load) << rule;
  // contact.csv: the plane touches the whole deformed bottom, and pushes with the applied load.
  const auto bottomCorner = u.at("bottom corner").get<std::vector<double>>();
  const double bottomArea = (L + bottomCorner[0]) * (L + bottomCorner[1]);
  const auto floor = test::readKeyedCsv(output / "contact.csv").at("floor").back().values;
  EXPECT_NEAR(floor[0], bottomArea, 1e-6 * bottomArea) << rule << ": contact area";
  EXPECT_NEAR(floor[1], load, 1e-6 * load) << rule << ": normal force";
  EXPECT_NEAR(floor[2], p / eps, 1e-6 * p / eps) << rule << ": largest penetration";
  EXPECT_EQ(floor[3], 9 * 4) << rule << ": active points (4 on each of the 3 x 3 bottom faces)";
}
}  // namespace

TEST(ContactPatch, BlockOnAPlaneCarriesTheAppliedPressureUniformlyGauss) { expectUniformContactPressure("gauss"); }
TEST(ContactPatch, BlockOnAPlaneCarriesTheAppliedPressureUniformlyNodal) { expectUniformContactPressure("nodal"); }

// The augmented Lagrangian with a penalty 100 times lower: a pure penalty would let the block sink
// p / eps = 1e-5 m (1 % of it); the Uzawa updates of the contact multipliers close the gap to
// within the gap tolerance while the plane still carries p, uniformly.
TEST(ContactPatch, AugmentedLagrangianMeetsTheGapToleranceAtAHundredthOfThePenalty) {
  const double lowEps = eps / 100, tolerance = 1e-10;
  const auto output = test::scratchDirectory("contact_patch_al");
  const auto s = test::runDeck(test::inputPath("verification/contact_patch_block.xml"),
                               {"Contact/floor/enforcement=augmented Lagrangian",
                                "Contact/floor/penalty=" + std::to_string(lowEps),
                                "Contact/floor/gap tolerance=1e-10"},
                               output);
  ASSERT_TRUE(s.at("converged").get<bool>());
  EXPECT_TRUE(s.at("contact").at("gap_tolerance_met").get<bool>());
  EXPECT_LE(s.at("contact").at("largest_gap_error").get<double>(), tolerance);
  const auto &u = s.at("final_displacement");
  for (const char *point : {"origin", "bottom edge", "bottom inner", "bottom corner"})
    EXPECT_LE(std::abs(u.at(point).get<std::vector<double>>()[2]), tolerance) << point;
  const auto top = u.at("top corner").get<std::vector<double>>();
  const double load = p * (L + top[0]) * (L + top[1]);
  const auto floor = test::readKeyedCsv(output / "contact.csv").at("floor").back().values;
  EXPECT_NEAR(floor[1] / floor[0], p, 1e-6 * p) << "mean contact pressure";
  EXPECT_NEAR(floor[1], load, 1e-6 * load) << "normal force";
  EXPECT_LE(floor[4], tolerance) << "largest gap error";
  const auto bottom = test::readKeyedCsv(output / "resultants.csv").at("zmin").back().values;
  EXPECT_NEAR(bottom[2], load, 1e-6 * load);
  int uzawa = 0, updates = 0;
  for (const auto &step : s.at("steps")) {
    uzawa += step.at("uzawa_iterations").get<int>();
    updates += step.at("contact_updates").get<int>();
  }
  // Each step needs updates (the penalty alone misses the tolerance by 1e5); the count is reported.
  EXPECT_GT(updates, 0);
  std::printf("augmented Lagrangian contact, eps = %.3g Pa/m: %d Uzawa solves, %d contact updates over %zu steps, "
              "largest gap error %.3g m\n", lowEps, uzawa, updates, s.at("steps").size(),
              s.at("contact").at("largest_gap_error").get<double>());
}
