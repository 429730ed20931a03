// Gravity through the full solve (inputs/verification/hanging_block.xml): the support's reaction
// equals the weight rho g V (a conservation law: to round-off), and at small load the bar's end
// sinks by rho g L^2 / (2 E), E = 3 mu (Timoshenko & Goodier, bar hanging under its own weight),
// within 0.2 % (the roller support's restraint of the top face's warping, ~nu r^2/L^2, and the
// finite strain of 3.5e-4). Supine posture turns the same weight along -x.
#include <Eigen/Core>
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

// The same bar hung from an elastic support (Boundary conditions/top/type = elastic): springs of
// total stiffness k in y on the top face's 4 nodes. They carry the weight (the reaction written
// for the support is the sum of the springs' forces, to 1e-9 of W), and, the axial stress being
// uniform over the section, the equal springs translate the bar rigidly by W / k: the bottom sinks
// by the fixed support's elongation plus W / k (superposition; the roller's warping restraint,
// ~1e-3 of the elongation, is the tolerance). k = 0.375 N/m makes W / k ten times the elongation.
TEST(ElasticSupport, HangingBarTranslatesByWeightOverStiffness) {
  const double k = 0.375, weight = rho * g * a * a * L;
  const auto fixed = test::runDeck(test::inputPath("verification/hanging_block.xml"), {},
                                   test::scratchDirectory("hanging_fixed"));
  const auto s = test::runDeck(test::inputPath("verification/hanging_block.xml"),
                               {"Boundary conditions/top/type=elastic", "Boundary conditions/top/stiffness=0.375"},
                               test::scratchDirectory("hanging_elastic"));
  ASSERT_TRUE(s.at("converged").get<bool>());
  const auto top = s.at("steps").back().at("reactions").at("top").get<std::vector<double>>();
  EXPECT_NEAR(top[1], weight, 1e-9 * weight);
  EXPECT_EQ(top[0], 0.0); // the springs act in y only
  EXPECT_NEAR(s.at("steps").front().at("reactions").at("top").get<std::vector<double>>()[1], 0.5 * weight,
              1e-9 * weight);
  const double uFixed = fixed.at("final_displacement").at("bottom axis").get<std::vector<double>>()[1];
  const double u = s.at("final_displacement").at("bottom axis").get<std::vector<double>>()[1];
  EXPECT_NEAR(u, uFixed - weight / k, 1e-3 * std::abs(uFixed));
  EXPECT_GT(weight / k, 9 * std::abs(uFixed)); // the spring's share dominates, so the check has teeth
}

// The tongue with an elastic hyoid (its attachment nodes fixed or on springs, doc/tongue.md): the jaw
// and the hyoid's springs still carry the weight to 1e-9, a soft hyoid (1000 N/m in all) lets the
// tongue base sink further than the fixed one, and a stiff one (1e5 N/m) gives the fixed
// attachment's tip displacement back to 0.5 % (measured 0.12 %).
TEST(ElasticSupport, TongueHyoidSpringsTendToTheFixedAttachment) {
  const double weight = rho * g * 1.0229167206054071e-4;
  const auto fixed = test::runDeck(test::inputPath("tongue/tongue_gravity.xml"), {},
                                   test::scratchDirectory("tongue_hyoid_fixed"));
  auto elastic = [&](const std::string &k) {
    return test::runDeck(test::inputPath("tongue/tongue_gravity.xml"),
                         {"Boundary conditions/hyoid/type=elastic", "Boundary conditions/hyoid/stiffness=" + k},
                         test::scratchDirectory("tongue_hyoid_" + k));
  };
  auto vec = [](const nlohmann::json &s, const char *group, const char *name) {
    const auto v = s.at(group).at(name).get<std::vector<double>>();
    return Eigen::Vector3d(v[0], v[1], v[2]);
  };
  const auto soft = elastic("1000"), stiff = elastic("1e5");
  for (const auto *s : {&soft, &stiff}) {
    ASSERT_TRUE(s->at("converged").get<bool>());
    const auto &r = s->at("steps").back().at("reactions");
    EXPECT_NEAR(r.at("jaw")[2].get<double>() + r.at("hyoid")[2].get<double>(), weight, 1e-9 * weight);
  }
  EXPECT_LT(vec(soft, "final_displacement", "base").z(), vec(fixed, "final_displacement", "base").z() - 0.5e-3);
  const Eigen::Vector3d tip = vec(fixed, "final_displacement", "tip");
  EXPECT_LT((vec(stiff, "final_displacement", "tip") - tip).norm(), 5e-3 * tip.norm());
}
