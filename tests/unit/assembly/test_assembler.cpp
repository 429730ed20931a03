// The distributed assembly and the solver pieces on a 2 x 2 x 2 block built without a deck (a
// neo-Hookean block, clamped at x = 0, under its own weight), on 1 rank and under mpiexec on 2:
// - the graph couples each node with exactly the nodes it shares an element with;
// - Dirichlet dofs hold their prescribed values, carry no residual, and their rows and columns
//   of the tangent hold only the diagonal;
// - the tangent is the derivative of the residual (central finite difference);
// - the mass matrix carries the block's mass rho V in each direction, consistent and lumped alike,
//   and its constrained rows and columns are empty where the tangent's are;
// - Newton (NOX, typed parameters) converges quadratically, the supports' reactions then balance
//   the block's weight, and the Uzawa loop brings a nearly incompressible block to its
//   dilatation tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <set>
#include <vector>

#include <Teuchos_CommHelpers.hpp>

#include "BlockFixture.hpp"
#include "assembly/ModelEvaluator.hpp"
#include "assembly/NullSpace.hpp"
#include "solvers/linear/LinearSolverFactory.hpp"
#include "solvers/nonlinear/NewtonSolver.hpp"
#include "solvers/incompressibility/UzawaLoop.hpp"

using namespace glossa;
using namespace glossa::assembly::testing;

namespace {
// The mesh node of every global node number (the layout renumbers nodes rank by rank).
std::vector<mesh::NodeId> meshNodeOfNumber(const assembly::DofLayout &layout) {
  std::vector<mesh::NodeId> node(layout.nodeNumber.size());
  for (std::size_t n = 0; n < node.size(); ++n) node[static_cast<std::size_t>(layout.nodeNumber[n])] = static_cast<mesh::NodeId>(n);
  return node;
}
} // namespace

TEST(Assembler, GraphCouplesEachNodeWithTheNodesOfItsElements) {
  const model::Scene scene = block(0.3);
  const AssemblerWithHistory built(scene, world());
  const assembly::Assembler &assembler = *built.assembler;
  const auto K = assembler.createMatrix();
  std::vector<std::set<mesh::NodeId>> neighbours(scene.mesh.nodes.size());
  for (const auto &hex : scene.mesh.elements)
    for (auto a : hex)
      for (auto b : hex) neighbours[a].insert(b);
  const auto map = assembler.layout().ownedMap();
  const auto nodeOf = meshNodeOfNumber(assembler.layout());
  ASSERT_EQ(map->getGlobalNumElements(), 3u * 27u);
  long long mine = 0, entries = 0;
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const auto gid = map->getGlobalElement(static_cast<assembly::LO>(i));
    const auto node = nodeOf[static_cast<std::size_t>(gid / 3)]; // dof = 3 number + component
    EXPECT_EQ(K->getNumEntriesInGlobalRow(gid), 3 * neighbours[node].size()) << "dof " << gid;
    mine += static_cast<long long>(K->getNumEntriesInGlobalRow(gid));
  }
  Teuchos::reduceAll(*world(), Teuchos::REDUCE_SUM, mine, Teuchos::outArg(entries));
  // 27 nodes: 8 corners with 8 neighbours, 12 edge midpoints with 12, 6 face centres with 18, the
  // centre with 27.
  std::size_t rows = 0;
  for (const auto &n : neighbours) rows += 3 * 3 * n.size();
  EXPECT_EQ(entries, static_cast<long long>(rows)); // every owned row once, over the ranks
  EXPECT_EQ(rows, 9u * (8 * 8 + 12 * 12 + 6 * 18 + 27));
}

TEST(Assembler, DirichletDofsHoldTheirValuesWithNoResidualAndADiagonalRow) {
  const Eigen::Vector3d g(1e-4, -2e-4, 3e-4);
  const model::Scene scene = block(0.3, g);
  const AssemblerWithHistory built(scene, world());
  const assembly::Assembler &assembler = *built.assembler;
  assembly::Vector u(assembler.layout().ownedMap()), f(assembler.layout().ownedMap());
  deform(built.results, u);
  assembler.applyDirichlet(u, 1.0);
  const auto K = assembler.createMatrix();
  const std::vector<double> lambda(assembler.layout().numLocalElements(), 0.0);
  ASSERT_TRUE(assembler.assemble(u, 1.0, lambda, nullptr, &f, K.get()).valid);
  const std::set<mesh::NodeId> clamped(scene.dirichlet[0].nodes.begin(), scene.dirichlet[0].nodes.end());
  const auto map = assembler.layout().ownedMap();
  const auto nodeOf = meshNodeOfNumber(assembler.layout());
  const auto uData = u.getData(0), fData = f.getData(0);
  int constrainedRows = 0;
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const auto gid = map->getGlobalElement(static_cast<assembly::LO>(i));
    const auto node = nodeOf[static_cast<std::size_t>(gid / 3)];
    const int c = static_cast<int>(gid % 3);
    typename assembly::CrsMatrix::nonconst_global_inds_host_view_type cols("cols", K->getNumEntriesInGlobalRow(gid));
    typename assembly::CrsMatrix::nonconst_values_host_view_type vals("vals", cols.extent(0));
    std::size_t n = 0;
    K->getGlobalRowCopy(gid, cols, vals, n);
    if (clamped.count(node)) {
      ++constrainedRows;
      EXPECT_EQ(uData[i], g[c]);
      EXPECT_EQ(fData[i], 0.0) << "dof " << gid;
      for (std::size_t k = 0; k < n; ++k) {
        if (cols(k) == gid) EXPECT_GT(vals(k), 0.0);
        else EXPECT_EQ(vals(k), 0.0) << "row " << gid << " column " << cols(k);
      }
    } else {
      // A free row has no coupling to a constrained column either.
      for (std::size_t k = 0; k < n; ++k) {
        if (clamped.count(nodeOf[static_cast<std::size_t>(cols(k) / 3)])) {
          EXPECT_EQ(vals(k), 0.0);
        }
      }
    }
  }
  int total = 0;
  Teuchos::reduceAll(*world(), Teuchos::REDUCE_SUM, constrainedRows, Teuchos::outArg(total));
  EXPECT_EQ(total, 27); // the 9 nodes of x = 0, 3 components each
}

TEST(Assembler, TangentIsTheCentralDifferenceOfTheResidual) {
  const model::Scene scene = block(0.45);
  const AssemblerWithHistory built(scene, world());
  const assembly::Assembler &assembler = *built.assembler;
  assembly::Vector u(assembler.layout().ownedMap());
  deform(built.results, u);
  assembler.applyDirichlet(u, 1.0);
  // A direction on the free dofs, of the size of the deformation.
  std::vector<double> all(3 * scene.mesh.nodes.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = 1e-4 * kSide * std::sin(1.7 * static_cast<double>(k) + 0.3);
  const TangentCheck check = centralDifferenceCheck(assembler, built.results, u, all, 1e-3);
  EXPECT_GT(check.scale, 0.0);
  char relative[32];
  std::snprintf(relative, sizeof relative, "%.3e", check.error / check.scale);
  RecordProperty("relative_error", relative);
  EXPECT_LT(check.error, 1e-6 * check.scale) << "|Kv| = " << check.scale;
}

namespace {
// The linear solver's context of a block built in code: its coordinates and rigid-body modes,
// symmetric, the solver type decided by the section.
solvers::LinearSolverContext linearSolverContext(const assembly::Assembler &assembler) {
  return {assembly::coordinates(assembler),
          assembly::rigidBodyModes(assembler),
          world()->getSize(),
          assembler.layout().numGlobalDofs(),
          true,
          std::nullopt};
}
}  // namespace

TEST(NewtonSolver, ConvergesQuadraticallyAndTheReactionsBalanceTheWeight) {
  const model::Scene scene = block(0.3);
  const AssemblerWithHistory built(scene, world());
  const auto assembler = built.assembler;
  const solvers::LinearSolverContext context = linearSolverContext(*assembler);
  const auto model = Teuchos::rcp(
      new assembly::ModelEvaluator(assembler, solvers::buildLinearSolver(solvers::LinearSolverParameters{}, context)));
  model->setTime(1.0);
  solvers::NewtonParameters parameters;
  parameters.residualTolerance = 1e-12;
  parameters.updateTolerance = 1e-14;
  const solvers::NewtonSolver newton(model, parameters, kSide, 1e-12);
  assembly::Vector u(assembler->layout().ownedMap());
  assembler->applyDirichlet(u, 1.0);
  const double load = assembler->externalForceNorm(1.0);
  const solvers::NewtonResult r = newton.solve(u, 1e-11 * load, nullptr);
  ASSERT_TRUE(r.converged);
  // Quadratic: from the first norm below 1e-3 of the start on, each is at most 10 x the square
  // of the one before (relative to the start).
  const auto &norms = r.residualNorms;
  ASSERT_GE(norms.size(), 3u);
  for (std::size_t k = 1; k + 1 < norms.size(); ++k)
    if (norms[k] < 1e-3 * norms[0] && norms[k + 1] > 1e-11 * norms[0]) { // above round-off
      EXPECT_LT(norms[k + 1] / norms[0], 10.0 * std::pow(norms[k] / norms[0], 2)) << "iteration " << k + 1;
    }
  // The support carries the whole weight, rho g V, and nothing sideways.
  const std::vector<double> lambda(assembler->layout().numLocalElements(), 0.0);
  const auto reactions = built.results.reactions(u, 1.0, lambda);
  ASSERT_EQ(reactions.size(), 1u);
  const double weight = kDensity * kGravity * kSide * kSide * kSide;
  EXPECT_NEAR(reactions[0].force.z() / weight, 1.0, 1e-9);
  EXPECT_NEAR(reactions[0].force.x() / weight, 0.0, 1e-9);
  EXPECT_NEAR(reactions[0].force.y() / weight, 0.0, 1e-9);
}

TEST(UzawaLoop, BringsANearlyIncompressibleBlockToItsDilatationTolerance) {
  // nu = 0.4999 (kappa = 5000 mu) in the law, kappa_AL = 30 mu in the tangent: the multipliers
  // carry the pressure, and every element's dilatation obeys the law to 1e-6.
  model::Scene scene = block(0.4999);
  solvers::IncompressibilityParameters incompressibility;
  incompressibility.dilatationTolerance = 1e-6;
  const std::vector<materials::VolumetricEnergy> physical{scene.tissues[0].volumetric};
  scene.tissues[0].volumetric = scene.tissues[0].volumetric.withKappa(
      solvers::Augmentation::tangentKappa(incompressibility, physical[0].kappa(), kMu));
  const double kappa = materials::bulkModulus(kMu, 0.4999), kappaAL = 30.0 * kMu;
  EXPECT_NEAR(scene.tissues[0].volumetric.kappa(), 1.0 / (1.0 / kappa + 1.0 / kappaAL), 1e-9 * kappaAL);
  const AssemblerWithHistory built(scene, world());
  const auto assembler = built.assembler;
  const solvers::LinearSolverContext context = linearSolverContext(*assembler);
  const auto model = Teuchos::rcp(new assembly::ModelEvaluator(
      assembler, solvers::buildLinearSolver(solvers::LinearSolverParameters{}, context)));
  model->setTime(1.0);
  const solvers::NewtonSolver newton(model, solvers::NewtonParameters{}, kSide, 1e-10);
  solvers::Augmentation augmentation(incompressibility, physical, {kMu});
  const solvers::UzawaLoop uzawa(built.results, newton, incompressibility, augmentation);
  assembly::Vector u(assembler->layout().ownedMap());
  std::vector<double> lambda(assembler->layout().numLocalElements(), 0.0);
  model->setMultipliers(lambda);
  const solvers::UzawaResult r = uzawa.solve(u, lambda, 1e-10 * assembler->externalForceNorm(1.0), nullptr, nullptr);
  ASSERT_TRUE(r.converged);
  EXPECT_GE(r.solves, 2); // the multipliers had to move
  EXPECT_LT(r.dilatation.max, 1e-6);
  const solvers::DilatationError e = uzawa.dilatationError(built.results.elementDilatations(u, lambda));
  EXPECT_LT(e.max, 1e-6);
}

namespace {
// The owned vector of a uniform velocity w at every node.
assembly::Vector translation(const assembly::Assembler &assembler, const Eigen::Vector3d &w) {
  assembly::Vector v(assembler.layout().ownedMap());
  auto data = v.getDataNonConst(0);
  for (std::size_t i = 0; i < static_cast<std::size_t>(data.size()); ++i)
    data[i] = w[static_cast<int>(i % 3)];
  return v;
}
double energyNorm(const assembly::FEMatrix &M, const assembly::Vector &v) {
  assembly::Vector Mv(v.getMap());
  M.apply(v, Mv);
  return v.dot(Mv);
}
} // namespace

TEST(Assembler, MassMatrixCarriesTheBlocksMassConsistentAndLumped) {
  const model::Scene scene = block(0.3);
  const AssemblerWithHistory built(scene, world());
  const assembly::Assembler &assembler = *built.assembler;
  const double mass = kDensity * kSide * kSide * kSide;
  const Eigen::Vector3d w(0.4, -1.1, 0.25);
  const assembly::Vector v = translation(assembler, w);
  double energies[2] = {0.0, 0.0};
  int k = 0;
  for (fem::MassLumping lumping : {fem::MassLumping::consistent, fem::MassLumping::lumped}) {
    const auto M = assembler.createMatrix();
    assembler.assembleMass(*M, lumping, assembly::Assembler::ConstrainedDofs::keep);
    // A rigid translation's kinetic energy (1/2) v.Mv = (1/2) m |w|^2: the mass is conserved.
    energies[k] = 0.5 * energyNorm(*M, v);
    EXPECT_NEAR(energies[k], 0.5 * mass * w.squaredNorm(), 1e-12 * mass) << "lumping " << k;
    ++k;
  }
  EXPECT_NEAR(energies[1], energies[0], 1e-13 * mass);
}

TEST(Assembler, MassMatrixLeavesConstrainedRowsAndColumnsEmptyForTheTangent) {
  const model::Scene scene = block(0.3);
  const AssemblerWithHistory built(scene, world());
  const assembly::Assembler &assembler = *built.assembler;
  const auto M = assembler.createMatrix();
  assembler.assembleMass(*M, fem::MassLumping::consistent, assembly::Assembler::ConstrainedDofs::zeroed);
  const assembly::Vector v = translation(assembler, Eigen::Vector3d(1.0, 0.0, 0.0));
  assembly::Vector Mv(v.getMap());
  M->apply(v, Mv);
  assembly::Vector masked(Mv, Teuchos::Copy);
  assembler.zeroConstrainedDofs(masked);
  masked.update(-1.0, Mv, 1.0);
  EXPECT_EQ(masked.normInf(), 0.0); // M v vanishes at every constrained row
  // v.Mv is the mass of the free rows and columns: in x, the 3-node chain of two linear elements
  // on [0, 2h] (matrix (h/6)[2 1; 1 2] each) without node 0's row (sum h/2) and column (h/2),
  // its diagonal h/3 counted in both; the y and z directions keep their whole length.
  const double h = kSide / 2.0;
  const double freeLength = 2.0 * h - h + h / 3.0;
  const double expected = kDensity * freeLength * kSide * kSide;
  EXPECT_NEAR(v.dot(Mv), expected, 1e-12 * expected);
}
