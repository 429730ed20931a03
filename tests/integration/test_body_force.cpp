// Gravity through the full solve (inputs/verification/hanging_block.xml): the support's reaction
// equals the weight rho g V (a conservation law: to round-off), and at small load the bar's end
// sinks by rho g L^2 / (2 E), E = 3 mu (Timoshenko & Goodier, bar hanging under its own weight),
// within 0.2 % (the roller support's restraint of the top face's warping, ~nu r^2/L^2, and the
// finite strain of 3.5e-4). Supine posture turns the same weight along -x.
#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {
const double rho = 1060.0, g = 9.81, mu = 1e5, L = 10e-3, a = 0.25e-3;
}

TEST(Gravity, HangingBarReactionAndElongation) {
  const auto s = test::runDeck(test::inputPath("verification/hanging_block.xml"), {}, test::scratchDirectory("hanging"));
  ASSERT_TRUE(s.at("converged").get<bool>());
  const double weight = rho * g * a * a * L;
  const auto &last = s.at("steps").back();
  const auto top = last.at("reactions").at("top").get<std::vector<double>>();
  EXPECT_NEAR(top[1], weight, 1e-9 * weight);
  EXPECT_NEAR(top[0], 0.0, 1e-12 * weight);
  const double halfway = s.at("steps").front().at("reactions").at("top").get<std::vector<double>>()[1];
  EXPECT_NEAR(halfway, 0.5 * weight, 1e-9 * weight); // the load ramps linearly in time
  const auto u = s.at("final_displacement").at("bottom axis").get<std::vector<double>>();
  const double exact = rho * g * L * L / (2 * 3 * mu);
  EXPECT_NEAR(-u[1], exact, 2e-3 * exact);
}

TEST(Gravity, SupinePostureActsAlongMinusX) {
  // Supine: gravity along -x. Held at x = 0 (the symmetry plane becomes the support).
  const auto s = test::runDeck(test::inputPath("verification/hanging_block.xml"),
                               {"Loads/weight/posture=supine"}, test::scratchDirectory("supine"));
  ASSERT_TRUE(s.at("converged").get<bool>());
  const auto &r = s.at("steps").back().at("reactions");
  EXPECT_NEAR(r.at("symmetry x").get<std::vector<double>>()[0], rho * g * a * a * L, 1e-9 * rho * g * a * a * L);
  EXPECT_NEAR(r.at("top").get<std::vector<double>>()[1], 0.0, 1e-9 * rho * g * a * a * L);
}

// The imported tongue (inputs/tongue/tongue_gravity.xml, ANSYS files): the jaw and hyoid
// attachments together carry its weight rho g V, V = 1.0229167206054071e-4 m^3 (the mesh's volume,
// tested two ways in unit_mesh), to 1e-9, and the tip sags.
TEST(Gravity, TongueAttachmentsCarryItsWeight) {
  const auto s = test::runDeck(test::inputPath("tongue/tongue_gravity.xml"), {}, test::scratchDirectory("tongue_gravity"));
  ASSERT_TRUE(s.at("converged").get<bool>());
  const auto &r = s.at("steps").back().at("reactions");
  const double weight = rho * g * 1.0229167206054071e-4;
  const auto jaw = r.at("jaw").get<std::vector<double>>(), hyoid = r.at("hyoid").get<std::vector<double>>();
  EXPECT_NEAR(jaw[2] + hyoid[2], weight, 1e-9 * weight);
  EXPECT_NEAR(jaw[0] + hyoid[0], 0.0, 1e-9 * weight);
  EXPECT_NEAR(jaw[1] + hyoid[1], 0.0, 1e-9 * weight);
  EXPECT_LT(s.at("final_displacement").at("tip").get<std::vector<double>>()[2], -1e-3);
}
