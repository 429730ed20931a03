// The muscle history: trial activation by backward Euler from the committed state (closed form
// of eq. 24), nothing committed by a step that is begun again (rollback), a controller's input
// override, and lambda_c trial values that become committed only on commit().
#include <gtest/gtest.h>

#include "materials/ContractileCurveSets.hpp"
#include "materials/FungIsotropic.hpp"
#include "model/MuscleHistory.hpp"

using namespace glossa;

namespace {
model::MuscleArchitecture architecture() {
  model::MuscleArchitecture a;
  model::MuscleGroup g;
  g.name = "GG";
  g.input = model::TimeFunction::steps({0.0, 0.1}, {1.0, 0.0}); // on, then off at 0.1 s
  a.groups.push_back(g);
  auto matrix = std::make_shared<materials::FungIsotropic>(materials::FungIsotropic::muscleMatrix());
  const auto geometry = materials::equalFractionFamilies({Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()});
  model::FibreRegion r;
  r.law = std::make_shared<materials::MuscleMaterial>(
      matrix, std::vector<materials::MuscleMaterial::Family>{
                  {geometry[0], materials::HillMuscleFibre::tableI(1.0, materials::physiologicalCurves())},
                  {geometry[1], materials::HillMuscleFibre::tableI(1.0, materials::physiologicalCurves())}});
  r.familyGroup = {0, -1}; // the second family is passive
  a.regions.push_back(r);
  a.elementRegion = {-1, 0};
  a.directions.resize(2);
  a.directions[1] = materials::FamilyDirections::Identity(3, 2);
  return a;
}
} // namespace

TEST(MuscleHistory, TrialActivationIsBackwardEulerFromTheCommittedState) {
  const auto a = architecture();
  model::MuscleHistory h(a, {0, 1});
  const double tau = 0.150;
  h.beginStep(0.01, 0.01);
  EXPECT_DOUBLE_EQ(h.trialActivation()[0], 0.01 / (tau + 0.01));
  // The step failed and is retried with half the step: from the committed alpha = 0 again.
  h.beginStep(0.005, 0.005);
  EXPECT_DOUBLE_EQ(h.trialActivation()[0], 0.005 / (tau + 0.005));
  EXPECT_EQ(h.committedActivation()[0], 0.0);
  h.commit();
  EXPECT_DOUBLE_EQ(h.committedActivation()[0], 0.005 / (tau + 0.005));
  EXPECT_EQ(h.committedTime(), 0.005);
  // u = 0 from 0.1 s: alpha decays with tau_F.
  h.beginStep(0.105, 0.1);
  const double a1 = 0.005 / (tau + 0.005);
  EXPECT_EQ(h.trialInput()[0], 0.0);
  EXPECT_DOUBLE_EQ(h.trialActivation()[0], a1 * tau / (tau + 0.1));
}

TEST(MuscleHistory, AControllersInputsAndFamilyActivation) {
  const auto a = architecture();
  model::MuscleHistory h(a, {0, 1});
  h.beginStep(0.01, 0.01, {0.5});
  EXPECT_EQ(h.trialInput()[0], 0.5);
  EXPECT_DOUBLE_EQ(h.trialActivation()[0], h.trialActivationForInput(0, 0.5));
  const auto alpha = h.familyActivation(1);
  ASSERT_EQ(alpha.size(), 2);
  EXPECT_DOUBLE_EQ(alpha(0), h.trialActivation()[0]);
  EXPECT_EQ(alpha(1), 0.0); // passive family
  // The next step without inputs follows the deck's u(t) again: nothing of the last one stays.
  h.beginStep(0.01, 0.01);
  EXPECT_EQ(h.trialInput()[0], 1.0);
  h.beginStep(0.01, 0.01, {1.7}); // clamped to [0, 1]
  EXPECT_EQ(h.trialInput()[0], 1.0);
  EXPECT_THROW(h.beginStep(0.01, 0.01, {0.5, 0.5}), std::invalid_argument);
  EXPECT_THROW(h.beginStep(0.01, 0.0), std::invalid_argument);
}

TEST(MuscleHistory, ContractileStretchCommitsOnlyOnCommit) {
  const auto a = architecture();
  model::MuscleHistory h(a, {1, 0}); // local order differs from mesh order
  EXPECT_EQ(h.familyCount(0), 2);
  EXPECT_EQ(h.familyCount(1), 0);
  for (int q = 0; q < 8; ++q) EXPECT_EQ(h.committedLambdaC(0, q)[1], 1.0); // zero-strain state
  h.beginStep(0.01, 0.01);
  h.trialLambdaC(0, 7)[1] = 0.98;
  EXPECT_EQ(h.committedLambdaC(0, 7)[1], 1.0);
  h.beginStep(0.01, 0.01); // retried: the trial value is discarded
  EXPECT_EQ(h.trialLambdaC(0, 7)[1], 1.0);
  h.trialLambdaC(0, 7)[1] = 0.97;
  h.commit();
  EXPECT_EQ(h.committedLambdaC(0, 7)[1], 0.97);
  EXPECT_EQ(h.committedLambdaC(0, 6)[1], 1.0);
}
