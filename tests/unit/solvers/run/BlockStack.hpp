#pragma once
// The solver stack the run's set-up builds, here by hand on the assembly tests' block
// (neo-Hookean, nu = 0.4999, clamped at x = 0, held by a symmetry plane at y = 0, under its own
// weight): the augmented Lagrangian at its default kappa_AL and the dilatation tolerance 1e-6; the
// scene keeps its physical law, the assembly reads the augmentation's tangent law.

#include <memory>

#include <Tpetra_Core.hpp>

#include "BlockFixture.hpp"
#include "assembly/Assembler.hpp"
#include "assembly/ModelEvaluator.hpp"
#include "assembly/NullSpace.hpp"
#include "assembly/ResultEvaluator.hpp"
#include "solvers/incompressibility/UzawaLoop.hpp"
#include "solvers/nonlinear/NewtonSolver.hpp"
#include "solvers/run/StepSolver.hpp"

namespace glossa::solvers::testing {
using assembly::testing::kDensity;
using assembly::testing::kGravity;
using assembly::testing::kMu;
using assembly::testing::kSide;
constexpr double kNu = 0.4999;

// The assembly tests' block, held by a symmetry plane at y = 0 as well.
inline model::Scene block() {
  model::Scene scene = assembly::testing::block(kNu);
  model::DirichletCondition symmetry;
  symmetry.name = "symmetry";
  symmetry.nodes = scene.mesh.nodeSets.at("ymin");
  symmetry.fixed = {false, true, false};
  scene.dirichlet.push_back(symmetry);
  return scene;
}

inline IncompressibilityParameters tight() {
  IncompressibilityParameters p;
  p.dilatationTolerance = 1e-6;
  return p;
}

struct Stack {
  explicit Stack(model::Scene blockScene = block()) : scene(std::move(blockScene)), incompressibility(tight()), augmentation(incompressibility, {scene.tissues[0].volumetric}, {kMu}) {
    const auto comm = Tpetra::getDefaultComm();
    assembly::DofLayout layout = assembly::distributeScene(scene, comm);
    history = std::make_unique<model::MuscleHistory>(scene.muscles, layout.localElements);
    assembler = Teuchos::rcp(
        new assembly::Assembler(scene, std::move(layout), *history, comm, &augmentation.tangentLaws()));
    LinearSolverContext context{assembly::coordinates(*assembler),
                                assembly::rigidBodyModes(*assembler),
                                comm->getSize(),
                                assembler->layout().numGlobalDofs(),
                                true,
                                std::nullopt};  // decided from the section
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
} // namespace glossa::solvers::testing
