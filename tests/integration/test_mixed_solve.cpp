// Incompressibility/method = mixed: element pressures as Newton unknowns, each step a block solve
// (GMRES, Teko block-triangular preconditioner). Eliminating the pressure element by element
// gives the condensed three-field step, so at a finite bulk modulus the mixed solve must reproduce
// the condensed (penalty) solve's element pressures and displacements; at nu = 0.5, which the
// condensed form cannot express, it must reach the limit the augmented Lagrangian approaches with
// a tight dilatation tolerance, with every element's volume kept to round-off; with a line search
// (the pressures are unknowns of NOX's product space) it gives the same answer. Fields are read
// from results.h5 of the last step.
#include <gtest/gtest.h>

#include <cmath>

#include "LastStepField.hpp"
#include "RunDeck.hpp"
#include "io/deck/DeckError.hpp"

using namespace glossa;
using test::lastStepField;
using test::maxAbs;

namespace {
// deal.II step-44, 4 elements per side, nu = 0.4999, t = 1 (doc/verification/step44_reference.md).
constexpr double kDealII4 = -0.789713e-3;

// Every step from the committed state: the formulations are compared from the same start (the
// linear predictor would start the mixed solve from extrapolated pressures and the condensed one
// from the pressures of an extrapolated displacement).
const std::vector<std::string> kTight = {"Mesh/Box/cells=4,4,4", "Output/every=10", "Linear solver/tolerance=1e-10",
                                         "Nonlinear solver/forcing term=constant", "Time/predictor=none"};

nlohmann::json run(std::vector<std::string> overrides, const std::string &name) {
  std::vector<std::string> o = kTight;
  o.insert(o.end(), overrides.begin(), overrides.end());
  return test::runDeck(test::inputPath("verification/step44_block.xml"), o, test::scratchDirectory(name));
}
} // namespace

TEST(MixedSolve, PressureEqualsTheCondensedElementPressure) {
  const auto condensed = run({"Incompressibility/method=penalty"}, "mixed_vs_condensed_penalty");
  const auto mixed = run({"Incompressibility/method=mixed"}, "mixed_vs_condensed_mixed");
  ASSERT_TRUE(condensed.at("converged").get<bool>() && mixed.at("converged").get<bool>());
  const auto pc = lastStepField(test::scratchDirectory("mixed_vs_condensed_penalty"), "pressure");
  const auto pm = lastStepField(test::scratchDirectory("mixed_vs_condensed_mixed"), "pressure");
  const auto uc = lastStepField(test::scratchDirectory("mixed_vs_condensed_penalty"), "displacement");
  const auto um = lastStepField(test::scratchDirectory("mixed_vs_condensed_mixed"), "displacement");
  ASSERT_EQ(pc.size(), 64u);
  ASSERT_EQ(pm.size(), pc.size());
  ASSERT_EQ(um.size(), uc.size());
  EXPECT_GT(maxAbs(pc), 1e8) << "the pressure under the 400 MPa patch";
  for (std::size_t i = 0; i < pc.size(); ++i) EXPECT_NEAR(pm[i], pc[i], 1e-7 * maxAbs(pc)) << "element " << i;
  for (std::size_t i = 0; i < uc.size(); ++i) EXPECT_NEAR(um[i], uc[i], 1e-8 * maxAbs(uc)) << "dof " << i;
  const double top = mixed.at("final_displacement").at("top_centre").at(1).get<double>();
  EXPECT_NEAR(top, kDealII4, 1e-5 * std::abs(kDealII4));
  // The same Newton iterates: eliminating dp element by element is the condensed step.
  for (std::size_t s = 0; s < mixed.at("steps").size(); ++s)
    EXPECT_EQ(mixed.at("steps")[s].at("newton_iterations").get<int>(),
              condensed.at("steps")[s].at("newton_iterations").get<int>()) << "step " << s;
}

TEST(MixedSolve, ExactIncompressibilityIsTheAugmentedLagrangianLimit) {
  const auto mixed = run({"Incompressibility/method=mixed", "Material/Poisson's ratio=0.5"}, "mixed_nu05");
  const auto al = run({"Incompressibility/method=augmented Lagrangian", "Material/Poisson's ratio=0.5",
                       "Incompressibility/dilatation tolerance=1e-8"},
                      "mixed_nu05_al");
  ASSERT_TRUE(mixed.at("converged").get<bool>() && al.at("converged").get<bool>());
  for (const auto &step : mixed.at("steps")) {
    EXPECT_EQ(step.at("uzawa_iterations").get<int>(), 1) << "no Uzawa loop";
    EXPECT_LT(step.at("max_volume_change").get<double>(), 1e-12) << "theta = 1 to round-off";
  }
  const auto pm = lastStepField(test::scratchDirectory("mixed_nu05"), "pressure");
  const auto pa = lastStepField(test::scratchDirectory("mixed_nu05_al"), "pressure");
  const auto um = lastStepField(test::scratchDirectory("mixed_nu05"), "displacement");
  const auto ua = lastStepField(test::scratchDirectory("mixed_nu05_al"), "displacement");
  ASSERT_EQ(pm.size(), pa.size());
  // A dilatation error of 1e-8 (the augmented Lagrangian's floor here is about 2e-10) leaves p
  // within kappa_AL x 1e-8 = 3e-7 mu of the limit, where max |p| is about 5 mu.
  EXPECT_GT(maxAbs(pa), 1e8) << "the pressure under the 400 MPa patch";
  for (std::size_t i = 0; i < pm.size(); ++i) EXPECT_NEAR(pm[i], pa[i], 1e-6 * maxAbs(pa)) << "element " << i;
  for (std::size_t i = 0; i < um.size(); ++i) EXPECT_NEAR(um[i], ua[i], 1e-6 * maxAbs(ua)) << "dof " << i;
}

// The pressures are unknowns of NOX's product space [u; p~], so a line search scales their step
// with the displacements': backtracking gives the condensed (full-step) solve's answer.
TEST(MixedSolve, LineSearchStepsThePressuresWithTheDisplacements) {
  const auto condensed = run({"Incompressibility/method=penalty"}, "mixed_ls_penalty");
  const auto mixed = run({"Incompressibility/method=mixed", "Nonlinear solver/line search=backtrack"}, "mixed_ls_mixed");
  ASSERT_TRUE(condensed.at("converged").get<bool>() && mixed.at("converged").get<bool>());
  const auto pc = lastStepField(test::scratchDirectory("mixed_ls_penalty"), "pressure");
  const auto pm = lastStepField(test::scratchDirectory("mixed_ls_mixed"), "pressure");
  ASSERT_EQ(pm.size(), pc.size());
  EXPECT_GT(maxAbs(pc), 1e8);
  for (std::size_t i = 0; i < pc.size(); ++i) EXPECT_NEAR(pm[i], pc[i], 1e-7 * maxAbs(pc)) << "element " << i;
  EXPECT_NEAR(mixed.at("final_displacement").at("top_centre").at(1).get<double>(), kDealII4, 1e-5 * std::abs(kDealII4));
}

TEST(MixedSolve, RefusesWhatItCannotDo) {
  EXPECT_THROW(run({"Incompressibility/method=mixed", "Linear solver/type=direct"}, "mixed_refused_direct"),
               io::DeckError);
  EXPECT_THROW(run({"Incompressibility/method=mixed", "Material/element=Q1"}, "mixed_refused_q1"), io::DeckError);
}
