// The step solver on a 2 x 2 x 2 block built without a deck (neo-Hookean, nu = 0.4999, clamped
// at x = 0, held by a symmetry plane at y = 0, under its own weight): a step's Uzawa loop brings
// every element to the dilatation tolerance and the supports then carry the block's weight (the
// balance of forces, an independent reference); a state with material across the symmetry plane
// is refused, naming the plane and the node; corners are measured, and an element folded through
// itself refuses the state. And the Newton solver's solve with the tangent its last solve left,
// against the tangent assembled at the converged state.
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
  s.solver->measureCorners(state, 0.0, a);
  EXPECT_DOUBLE_EQ(a.minCornerJ, 1.0); // the reference state
  EXPECT_EQ(a.turnedOver, 0.0);
  EXPECT_TRUE(a.ok);
}

// The node at (side, side, side) belongs to one element of the 2 x 2 x 2 block; pushed to that
// cube's centre it folds it through itself (0.31 % of its volume turned over,
// tests/unit/fem/test_turned_over_volume.cpp): the state is refused, naming the element, its
// reference centroid and the time.
TEST(StepSolver, AStateWithAFoldedElementIsRefusedNamingIt) {
  Stack s;
  StepState state(s.assembler->layout().ownedMap(), s.assembler->layout().numLocalElements());
  const mesh::HexMesh &mesh = s.scene.mesh;
  std::size_t corner = 0, element = 0;
  for (std::size_t n = 0; n < mesh.numNodes(); ++n)
    if (mesh.nodes[n].isApprox(Eigen::Vector3d::Constant(kSide))) corner = n;
  for (std::size_t e = 0; e < mesh.numElements(); ++e)
    for (const auto n : mesh.elements[e])
      if (static_cast<std::size_t>(n) == corner) element = e;
  const Eigen::Vector3d centre = Eigen::Vector3d::Constant(0.75 * kSide), move = centre - mesh.nodes[corner];
  std::vector<double> all(3 * mesh.numNodes(), 0.0);
  for (int c = 0; c < 3; ++c) all[3 * corner + c] = move(c);
  assembly::ResultEvaluator(*s.assembler).scatterDisplacement(all, state.u);
  StepAttempt a;
  a.ok = true;
  s.solver->measureCorners(state, 0.5, a);
  EXPECT_FALSE(a.ok);
  EXPECT_NEAR(a.turnedOver, 0.003076, 2e-5);
  ASSERT_FALSE(a.folded.is_null());
  EXPECT_EQ(a.folded["element"].get<std::size_t>(), element);
  EXPECT_EQ(a.folded["time"].get<double>(), 0.5);
  EXPECT_NEAR(a.folded["min_corner_J"].get<double>(), -0.5, 1e-12);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.folded["reference_centroid"][c].get<double>(), centre(c), 1e-12 * kSide);
  EXPECT_NE(a.why.find("element " + std::to_string(element) + " "), std::string::npos) << a.why;
  EXPECT_NE(a.why.find("folded through itself"), std::string::npos) << a.why;
}

// The Uzawa loop's outer condition (the airflow's coupling, doc/airflow.md): the loop goes on past
// the dilatation tolerance while the condition is not met, ends on a solve where everything is,
// and stops unconverged, saying so, when the condition fails.
TEST(StepSolver, TheUzawaLoopIteratesItsOuterConditionToo) {
  Stack s;
  StepState state(s.assembler->layout().ownedMap(), s.assembler->layout().numLocalElements());
  const NewtonSolver::ToleranceRule rule = [](double initial) { return 1e-8 * std::max(initial, 1.0); };
  const UzawaResult plain = s.uzawa->solve(state.u, state.lambda, rule, {}, {});
  ASSERT_TRUE(plain.converged);
  // From the converged state the volume needs no more solves; the condition asks for 3 more.
  int calls = 0;
  const UzawaLoop::OuterCondition threeUpdates = [&](const assembly::Vector &) {
    return ++calls <= 3 ? UzawaLoop::OuterVerdict::updated : UzawaLoop::OuterVerdict::met;
  };
  const UzawaResult more = s.uzawa->solve(state.u, state.lambda, rule, {}, {}, threeUpdates);
  EXPECT_TRUE(more.converged);
  EXPECT_EQ(calls, 4);
  EXPECT_EQ(more.solves, 4);
  EXPECT_LT(more.dilatation.max, 1e-6);
  const UzawaLoop::OuterCondition failing = [](const assembly::Vector &) { return UzawaLoop::OuterVerdict::failed; };
  const UzawaResult failed = s.uzawa->solve(state.u, state.lambda, rule, {}, {}, failing);
  EXPECT_FALSE(failed.converged);
  EXPECT_TRUE(failed.outerFailed);
  EXPECT_EQ(failed.solves, 1);
}

// NewtonSolver::solveWithLastTangent (the airflow coupling's Jacobian, doc/airflow.md) solves with
// the linear solver the last Newton solve left: nothing before a solve; after one, the answer of
// the tangent at the converged state (solveTangent, assembled and factored there afresh) to the
// difference between that tangent and the last one assembled, and far from the reference state's.
TEST(NewtonSolver, TheLastTangentSolvesAsTheTangentAtTheConvergedState) {
  Stack s;
  StepState state(s.assembler->layout().ownedMap(), s.assembler->layout().numLocalElements());
  const auto map = s.assembler->layout().ownedMap();
  assembly::MultiVector rhs(map, 2), last(map, 2), converged(map, 2), atRest(map, 2);
  EXPECT_THROW(s.newton->solveWithLastTangent(rhs, last, 1e-10), std::runtime_error);

  const StepAttempt a = s.solver->solve(1.0, 1.0, state, true);
  ASSERT_TRUE(a.ok) << a.why;
  // The weight's load, and a lateral pull on every free dof.
  rhs.getVectorNonConst(0)->assign(s.assembler->loadResidual(state.u, 1.0));
  rhs.getVectorNonConst(1)->putScalar(1e-6);
  s.assembler->zeroConstrainedDofs(*rhs.getVectorNonConst(1));
  s.newton->solveWithLastTangent(rhs, last, 1e-10);
  s.newton->solveTangent(state.u, rhs, converged, 1e-10);
  const assembly::Vector zero(map);
  s.newton->solveTangent(zero, rhs, atRest, 1e-10);
  for (std::size_t j = 0; j < 2; ++j) {
    assembly::Vector toLast(map), toRest(map);
    toLast.update(1.0, *last.getVector(j), -1.0, *converged.getVector(j), 0.0);
    toRest.update(1.0, *atRest.getVector(j), -1.0, *converged.getVector(j), 0.0);
    const double scale = converged.getVector(j)->norm2();
    ASSERT_GT(scale, 0.0);
    EXPECT_LT(toLast.norm2(), 1e-6 * scale) << "column " << j;
    EXPECT_GT(toRest.norm2(), 1e-3 * scale) << "column " << j; // the test can tell the states apart
    std::printf("column %zu: last tangent %.3e, reference state %.3e of the converged answer\n", j,
                toLast.norm2() / scale, toRest.norm2() / scale);
  }
}
