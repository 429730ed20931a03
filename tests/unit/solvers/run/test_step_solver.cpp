// The step solver on a 2 x 2 x 2 block built without a deck (neo-Hookean, nu = 0.4999, clamped
// at x = 0, held by a symmetry plane at y = 0, under its own weight): a step's Uzawa loop brings
// every element to the dilatation tolerance and the supports then carry the block's weight (the
// balance of forces, an independent reference); a state with material across the symmetry plane
// is refused, naming the plane and the node; corners are measured.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include "assembly/Assembler.hpp"
#include "assembly/ModelEvaluator.hpp"
#include "assembly/NullSpace.hpp"
#include "assembly/ResultEvaluator.hpp"
#include "materials/NeoHookean.hpp"
#include "mesh/BoxGenerator.hpp"
#include "solvers/incompressibility/UzawaLoop.hpp"
#include "solvers/nonlinear/NewtonSolver.hpp"
#include "solvers/run/StepSolver.hpp"

using namespace glossa;
using namespace glossa::solvers;

namespace {
constexpr double kSide = 1e-2, kMu = 1e4, kNu = 0.4999, kDensity = 1000.0, kGravity = 9.81;

model::Scene block() {
  model::Scene scene;
  scene.mesh = mesh::generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(kSide), {2, 2, 2});
  model::Tissue tissue;
  tissue.name = "block";
  tissue.matrix = std::make_shared<materials::NeoHookean>(kMu);
  tissue.volumetric = materials::VolumetricEnergy(materials::VolumetricEnergy::Form::SimoTaylor,
                                                  materials::bulkModulus(kMu, kNu));
  tissue.density = kDensity;
  scene.tissues.push_back(tissue);
  model::DirichletCondition clamp;
  clamp.name = "clamp";
  clamp.nodes = scene.mesh.nodeSets.at("xmin");
  clamp.fixed = {true, true, true};
  scene.dirichlet.push_back(clamp);
  model::DirichletCondition symmetry;
  symmetry.name = "symmetry";
  symmetry.nodes = scene.mesh.nodeSets.at("ymin");
  symmetry.fixed = {false, true, false};
  scene.dirichlet.push_back(symmetry);
  model::BodyForceLoad weight;
  weight.name = "weight";
  for (std::size_t e = 0; e < scene.mesh.numElements(); ++e) weight.elements.push_back(static_cast<mesh::ElementId>(e));
  weight.acceleration = Eigen::Vector3d(0.0, 0.0, -kGravity);
  scene.bodyForces.push_back(weight);
  return scene;
}

// The solver stack a run's set-up builds, here by hand: the augmented Lagrangian at its default
// kappa_AL, the dilatation tolerance 1e-6; the scene keeps its physical law, the assembly reads
// the augmentation's tangent law.
IncompressibilityParameters tight() {
  IncompressibilityParameters p;
  p.dilatationTolerance = 1e-6;
  return p;
}

struct Stack {
  Stack() : scene(block()), incompressibility(tight()), augmentation(incompressibility, {scene.tissues[0].volumetric}, {kMu}) {
    const auto comm = Tpetra::getDefaultComm();
    assembly::DofLayout layout = assembly::distributeScene(scene, comm);
    history = std::make_unique<model::MuscleHistory>(scene.muscles, layout.localElements);
    assembler = Teuchos::rcp(
        new assembly::Assembler(scene, std::move(layout), *history, comm, &augmentation.tangentLaws()));
    LinearSolverContext context{assembly::coordinates(*assembler), assembly::rigidBodyModes(*assembler), comm->getSize(),
                                assembler->layout().numGlobalDofs(), true};
    evaluator = Teuchos::rcp(new assembly::ModelEvaluator(assembler, buildLinearSolver(LinearSolverParameters{}, context)));
    newton = std::make_unique<NewtonSolver>(evaluator, NewtonParameters{}, kSide, 1e-10);
    uzawa = std::make_unique<UzawaLoop>(assembly::ResultEvaluator(*assembler), *newton, incompressibility, augmentation);
    solver = std::make_unique<StepSolver>(StepSolverParts{*assembler, *evaluator, *newton, *uzawa, *history}, scene,
                                          ReuseScope::newtonSolve, false);
  }
  const model::Scene scene;
  IncompressibilityParameters incompressibility;
  Augmentation augmentation;
  std::unique_ptr<model::MuscleHistory> history;
  Teuchos::RCP<assembly::Assembler> assembler;
  Teuchos::RCP<assembly::ModelEvaluator> evaluator;
  std::unique_ptr<NewtonSolver> newton;
  std::unique_ptr<UzawaLoop> uzawa;
  std::unique_ptr<StepSolver> solver;
};
} // namespace

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
