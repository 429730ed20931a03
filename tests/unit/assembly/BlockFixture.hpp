#pragma once
// The block the distributed assembly tests share, built without a deck: 2 x 2 x 2 cells of a
// 1 cm cube, neo-Hookean, clamped at x = 0, under its own weight; the assembler with the muscle
// history it reads and its result evaluator, owned side by side as the simulation owns them.

#include <cmath>
#include <memory>
#include <vector>

#include <Tpetra_Core.hpp>

#include "assembly/Assembler.hpp"
#include "assembly/ResultEvaluator.hpp"
#include "materials/NeoHookean.hpp"
#include "mesh/BoxGenerator.hpp"

namespace glossa::assembly::testing {

constexpr double kSide = 1e-2, kMu = 1e4, kDensity = 1000.0, kGravity = 9.81;

// mu = 10 kPa, nu as given, clamped on x = 0 (all three components, the values `clamp`), its
// weight along -z.
inline model::Scene block(double nu, const Eigen::Vector3d &clamp = Eigen::Vector3d::Zero()) {
  model::Scene scene;
  scene.mesh = mesh::generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(kSide), {2, 2, 2});
  model::Tissue tissue;
  tissue.name = "block";
  tissue.matrix = std::make_shared<materials::NeoHookean>(kMu);
  tissue.volumetric = materials::VolumetricEnergy(materials::VolumetricEnergy::Form::SimoTaylor,
                                                  materials::bulkModulus(kMu, nu));
  tissue.density = kDensity;
  scene.tissues.push_back(tissue);
  model::DirichletCondition clamped;
  clamped.name = "clamp";
  clamped.nodes = scene.mesh.nodeSets.at("xmin");
  clamped.fixed = {true, true, true};
  clamped.value = clamp;
  scene.dirichlet.push_back(clamped);
  model::BodyForceLoad weight;
  weight.name = "weight";
  for (std::size_t e = 0; e < scene.mesh.numElements(); ++e) weight.elements.push_back(static_cast<mesh::ElementId>(e));
  weight.acceleration = Eigen::Vector3d(0.0, 0.0, -kGravity);
  scene.bodyForces.push_back(weight);
  return scene;
}

inline Teuchos::RCP<const Comm> world() { return Tpetra::getDefaultComm(); }

// A smooth displacement field (a bend and a stretch, 2 % of the side) on the free dofs.
inline void deform(const ResultEvaluator &results, Vector &u) {
  const auto &nodes = results.scene().mesh.nodes;
  std::vector<double> all(3 * nodes.size());
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const Eigen::Vector3d X = nodes[n] / kSide;
    all[3 * n] = 0.02 * kSide * X.x() * X.y();
    all[3 * n + 1] = -0.01 * kSide * X.x() * X.x();
    all[3 * n + 2] = 0.015 * kSide * X.x() * (1.0 + X.z());
  }
  results.scatterDisplacement(all, u);
}

// The tangent at u (free dofs) against the central difference of the residual along the
// direction `all` (per mesh dof, zeroed at the constrained ones) with step h: the largest
// |K v - (f(u + h v) - f(u - h v)) / 2h| and the largest |K v|.
struct TangentCheck {
  double error = 0, scale = 0;
};
inline TangentCheck centralDifferenceCheck(const Assembler &assembler, const ResultEvaluator &results,
                                           const Vector &u, const std::vector<double> &all, double h) {
  const auto map = assembler.layout().ownedMap();
  Vector v(map), Kv(map), fPlus(map), fMinus(map), f(map);
  results.scatterDisplacement(all, v);
  assembler.zeroConstrainedDofs(v);
  const std::vector<double> lambda(assembler.layout().numLocalElements(), 0.0);
  const auto K = assembler.createMatrix();
  if (!assembler.assemble(u, 1.0, lambda, nullptr, &f, K.get()).valid) return {INFINITY, 0.0};
  K->apply(v, Kv);
  Vector up(u, Teuchos::Copy), um(u, Teuchos::Copy);
  up.update(h, v, 1.0);
  um.update(-h, v, 1.0);
  if (!assembler.assemble(up, 1.0, lambda, nullptr, &fPlus, nullptr).valid ||
      !assembler.assemble(um, 1.0, lambda, nullptr, &fMinus, nullptr).valid)
    return {INFINITY, 0.0};
  fPlus.update(-1.0 / (2.0 * h), fMinus, 1.0 / (2.0 * h)); // (f(u + h v) - f(u - h v)) / 2h
  assembler.zeroConstrainedDofs(Kv);                       // the Dirichlet rows' diagonal acts on v = 0 there
  fPlus.update(-1.0, Kv, 1.0);
  return {fPlus.normInf(), Kv.normInf()};
}

struct AssemblerWithHistory {
  AssemblerWithHistory(const model::Scene &scene, const Teuchos::RCP<const Comm> &comm)
      : layout(distributeScene(scene, comm)), history(scene.muscles, layout.localElements),
        assembler(Teuchos::rcp(new Assembler(scene, layout, history, comm))), results(*assembler) {}
  DofLayout layout;
  model::MuscleHistory history;
  Teuchos::RCP<Assembler> assembler;
  ResultEvaluator results;
};

} // namespace glossa::assembly::testing
