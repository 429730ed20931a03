// The path watch on the block of BlockStack.hpp with its weight ramped over t in [0, 1], a path
// that is nearly linear (strains of about rho g L / mu = 1 %): the stiffness along the path after
// each converged step stays that of the first (the relative stiffness is 1 by definition at the
// first step and, for a linear problem, at every step; here within 5 %, a few times the strain
// that sets the size of the nonlinear terms), nothing softens, and a refused step does
// not locate a limit point while the step can still be cut back; the watch's state survives a
// checkpoint.
#include <gtest/gtest.h>

#include "BlockStack.hpp"
#include "solvers/incompressibility/ConstrainedTangent.hpp"
#include "solvers/run/PathWatch.hpp"

using namespace glossa;
using namespace glossa::solvers;
using namespace glossa::solvers::testing;

namespace {
model::Scene rampedBlock() {
  model::Scene scene = block();
  scene.bodyForces[0].scale = model::TimeFunction::ramp(1.0);
  return scene;
}
} // namespace

TEST(PathWatch, AlongANearlyLinearPathTheStiffnessStaysThatOfTheFirstStep) {
  Stack s(rampedBlock());
  PathWatch watch(*s.assembler, *s.evaluator, *s.newton, 0.25, 0.01, false);
  StepState committed(s.assembler->layout().ownedMap(), s.assembler->layout().numLocalElements());
  for (int k = 1; k <= 3; ++k) {
    StepTrial trial(0.25 * k, 0.25, 0.0, committed);
    trial.attempt = s.solver->solve(trial.time, trial.dt, trial.state, true);
    ASSERT_TRUE(trial.attempt.ok) << trial.attempt.why;
    watch.check(trial);
    EXPECT_TRUE(trial.attempt.ok);
    EXPECT_FALSE(trial.attempt.unstable);
    EXPECT_NEAR(trial.attempt.pathStiffness, 1.0, k == 1 ? 1e-12 : 5e-2) << "step " << k;
    watch.accepted(trial.time, trial.attempt.pathStiffness);
    committed.assign(trial.state);
  }
  EXPECT_FALSE(watch.state()["softening_said"].get<bool>());
  // A step refused for another reason (Newton), with room left to cut back: no limit point.
  StepTrial refused(1.0, 0.25, 0.0, committed);
  refused.attempt.why = "Newton did not converge";
  EXPECT_FALSE(watch.refused(0.75, refused, committed, 0.125, true).located);
  // The watch's state comes back from a checkpoint's.
  PathWatch restored(*s.assembler, *s.evaluator, *s.newton, 0.25, 0.01, false);
  restored.restore(watch.state());
  EXPECT_EQ(restored.state(), watch.state());
}

// Under the augmented Lagrangian near a limit point (ConstrainedTangent): at a converged state of
// the block, the constrained laws with their multipliers Lambda_c give every element the pressure
// and the residual the state has (to round-off), the augmented laws come back afterwards, and the
// watch raises kappa_AL to 300 mu once, when the path has softened.
TEST(PathWatch, TheConstrainedTangentKeepsTheStateAndASoftenedPathRaisesKappaAL) {
  Stack s(rampedBlock());
  StepState state(s.assembler->layout().ownedMap(), s.assembler->layout().numLocalElements());
  ASSERT_TRUE(s.solver->solve(1.0, 1.0, state, true).ok);
  const assembly::ResultEvaluator results(*s.assembler);
  const auto before = results.elementDilatations(state.u, state.lambda);
  assembly::Vector f(state.u.getMap()), fc(state.u.getMap());
  ASSERT_TRUE(s.assembler->assemble(state.u, 1.0, state.lambda, nullptr, &f, nullptr).valid);
  const double kappaT = s.augmentation.tangentLaws()[0].kappa();
  {
    const ConstrainedTangent constrained(s.augmentation, results, state.u, state.lambda);
    EXPECT_EQ(s.augmentation.tangentLaws()[0].kappa(), s.augmentation.physicalLaw(0).kappa()); // nu = 0.4999: below the cap
    const auto after = results.elementDilatations(state.u, constrained.multipliers());
    double scale = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < before.pressure.size(); ++i) {
      scale = std::max(scale, std::abs(before.pressure[i]));
      worst = std::max(worst, std::abs(after.pressure[i] - before.pressure[i]));
    }
    EXPECT_LT(worst, 1e-9 * scale);
    ASSERT_TRUE(s.assembler->assemble(state.u, 1.0, constrained.multipliers(), nullptr, &fc, nullptr).valid);
    fc.update(-1.0, f, 1.0);
    EXPECT_LT(fc.norm2(), 1e-9 * s.assembler->externalForceNorm(1.0));
  }
  EXPECT_EQ(s.augmentation.tangentLaws()[0].kappa(), kappaT);

  PathWatch watch(*s.assembler, *s.evaluator, *s.newton, 0.25, 0.01, false, &s.augmentation);
  watch.accepted(0.25, 0.5);
  EXPECT_EQ(s.augmentation.ratios()[0], 30.0);
  watch.accepted(0.5, 0.05);
  EXPECT_EQ(s.augmentation.ratios()[0], PathWatch::kNearLimitPointRatio);
  EXPECT_GT(s.augmentation.tangentLaws()[0].kappa(), kappaT);
}
