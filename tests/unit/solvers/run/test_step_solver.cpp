// The step solver on a 2 x 2 x 2 block built without a deck (neo-Hookean, nu = 0.4999, clamped
// at x = 0, held by a symmetry plane at y = 0, under its own weight): a step's Uzawa loop brings
// every element to the dilatation tolerance and the supports then carry the block's weight (the
// balance of forces, an independent reference); a state with material across the symmetry plane
// is refused, naming the plane and the node; corners are measured.
#include <gtest/gtest.h>

#include "BlockStack.hpp"

using namespace glossa;
using namespace glossa::solvers;
using namespace glossa::solvers::testing;

TEST(StepSolver, AStepReachesTheDilatationToleranceAndTheSupportsCarryTheWeight) {
  Stack s;
  StepState state(s.assembler->layout().ownedMap(), s.assembler->layout().numLocalElements());
  const StepAttempt a = s.solver->solve(1.0, 1.0, state, true);
  ASSERT_TRUE(a.ok) << a.why;
  EXPECT_LT(a.uzawa.dilatation.max, 1e-6);
  EXPECT_GE(a.uzawa.solves, 2); // the multipliers had to move
  EXPECT_GT(a.minCornerJ, 0.9);
  EXPECT_LE(a.minCornerJ, a.minRegularCornerJ);
  EXPECT_TRUE(a.insideOut.is_null());
  // The supports' vertical reactions balance the weight rho g V.
  double lift = 0.0;
  for (const auto &r : assembly::ResultEvaluator(*s.assembler).reactions(state.u, 1.0, state.lambda)) lift += r.force.z();
  const double weight = kDensity * kGravity * kSide * kSide * kSide;
  EXPECT_NEAR(lift, weight, 1e-6 * weight);
}

TEST(StepSolver, AStateAcrossItsSymmetryPlaneIsRefused) {
  Stack s;
  StepState state(s.assembler->layout().ownedMap(), s.assembler->layout().numLocalElements());
  // The node at (side, side, side) moved to y = -side / 2: across the plane y = 0.
  std::vector<double> all(3 * s.scene.mesh.numNodes(), 0.0);
  std::size_t corner = 0;
  for (std::size_t n = 0; n < s.scene.mesh.numNodes(); ++n)
    if (s.scene.mesh.nodes[n].isApprox(Eigen::Vector3d::Constant(kSide))) corner = n;
  all[3 * corner + 1] = -1.5 * kSide;
  assembly::ResultEvaluator(*s.assembler).scatterDisplacement(all, state.u);
  StepAttempt a;
  a.ok = true;
  s.solver->refuseInsideOut(state, a);
  EXPECT_FALSE(a.ok);
  EXPECT_NE(a.why.find("symmetry plane 'symmetry' (y = 0 m)"), std::string::npos) << a.why;
  EXPECT_EQ(a.insideOut["node"], corner);
  EXPECT_NEAR(a.insideOut["distance"].get<double>(), 0.5 * kSide, 1e-15);
}

TEST(StepSolver, AStateOnItsSideOfThePlaneIsKept) {
  Stack s;
  StepState state(s.assembler->layout().ownedMap(), s.assembler->layout().numLocalElements());
  StepAttempt a;
  a.ok = true;
  s.solver->refuseInsideOut(state, a);
  EXPECT_TRUE(a.ok);
  s.solver->measureCorners(state, a);
  EXPECT_DOUBLE_EQ(a.minCornerJ, 1.0); // the reference state
}
