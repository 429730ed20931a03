// The contact patch test through the full solve (inputs/verification/contact_patch_block.xml): a
// block pressed onto a rigid plane by a uniform follower pressure p on its top is in homogeneous
// uniaxial compression, so the plane must carry p uniformly. With the penalty method the contact
// pressure at a point is eps times its penetration: every traced bottom node (the origin, an edge,
// an inner node, the far corner) sinks by p / eps to 1e-6, and the bottom's resultant (the force
// the plane exerts) equals the applied load, p times the deformed top area, to 1e-6. Both contact
// point rules pass on the box's rectangular faces (doc/contact.md).
#include <cmath>

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
}
}  // namespace

TEST(ContactPatch, BlockOnAPlaneCarriesTheAppliedPressureUniformlyGauss) { expectUniformContactPressure("gauss"); }
TEST(ContactPatch, BlockOnAPlaneCarriesTheAppliedPressureUniformlyNodal) { expectUniformContactPressure("nodal"); }
