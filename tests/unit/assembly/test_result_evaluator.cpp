// The result evaluator on the block of BlockFixture.hpp, on 1 rank and under mpiexec on 2:
// - gathers and scatters between distributed vectors and whole-mesh arrays are inverse;
// - the element dilatations without the point laws are those of the full element pass (Q1-P0);
// - the undeformed block has unit dilatation and unit corner Jacobians;
// - the volume the whole boundary encloses is the sum of the elements' deformed volumes;
// - with no load on the surface, a clamped face's resultant is its condition's reaction.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <Teuchos_CommHelpers.hpp>

#include "BlockFixture.hpp"

using namespace glossa;
using namespace glossa::assembly::testing;

TEST(ResultEvaluator, GathersAndScattersAreInverse) {
  const model::Scene scene = block(0.3);
  const AssemblerWithHistory built(scene, world());
  const assembly::ResultEvaluator &results = built.results;
  std::vector<double> nodal(3 * scene.mesh.numNodes());
  for (std::size_t k = 0; k < nodal.size(); ++k) nodal[k] = std::sin(0.7 * static_cast<double>(k) + 0.1);
  assembly::Vector u(built.assembler->layout().ownedMap());
  results.scatterDisplacement(nodal, u);
  EXPECT_EQ(results.gatherDisplacement(u), nodal);
  std::vector<double> perElement(scene.mesh.numElements());
  for (std::size_t e = 0; e < perElement.size(); ++e) perElement[e] = 1.5 + static_cast<double>(e);
  const std::vector<double> local = results.localElementValues(perElement);
  EXPECT_EQ(local.size(), built.assembler->layout().numLocalElements());
  EXPECT_EQ(results.gatherElementField(local, 1), perElement);
  EXPECT_THROW(results.scatterDisplacement(std::vector<double>(5), u), std::invalid_argument);
}

TEST(ResultEvaluator, DilatationsWithoutThePointLawsAreThoseOfTheElementPass) {
  const model::Scene scene = block(0.45);
  const AssemblerWithHistory built(scene, world());
  assembly::Vector u(built.assembler->layout().ownedMap());
  deform(built.results, u);
  std::vector<double> lambda(built.assembler->layout().numLocalElements());
  for (std::size_t i = 0; i < lambda.size(); ++i) lambda[i] = 100.0 * static_cast<double>(i % 3);
  const assembly::ElementFields full = built.results.elementFields(u, lambda);
  const assembly::ElementFields fast = built.results.elementDilatations(u, lambda);
  ASSERT_EQ(fast.theta.size(), full.theta.size());
  for (std::size_t i = 0; i < full.theta.size(); ++i) {
    EXPECT_NEAR(fast.theta[i], full.theta[i], 1e-13) << "element " << i;
    EXPECT_NEAR(fast.pressure[i], full.pressure[i], 1e-9 * kMu) << "element " << i;
    EXPECT_NEAR(fast.referenceVolume[i], full.referenceVolume[i], 1e-13 * kSide * kSide * kSide) << "element " << i;
  }
}

TEST(ResultEvaluator, TheUndeformedBlockHasUnitDilatationAndCorners) {
  const model::Scene scene = block(0.3);
  const AssemblerWithHistory built(scene, world());
  const assembly::Vector u(built.assembler->layout().ownedMap());
  const std::vector<double> lambda(built.assembler->layout().numLocalElements(), 0.0);
  const assembly::ElementFields fields = built.results.elementFields(u, lambda);
  for (std::size_t i = 0; i < fields.theta.size(); ++i) {
    EXPECT_NEAR(fields.theta[i], 1.0, 1e-14);
    EXPECT_NEAR(fields.minJ[i], 1.0, 1e-14);
    EXPECT_NEAR(fields.pressure[i], 0.0, 1e-9 * kMu);
  }
  const auto worst = built.results.worstCorner(u);
  EXPECT_NEAR(worst.J, 1.0, 1e-14);
  EXPECT_NEAR(worst.regularJ, 1.0, 1e-14);
  EXPECT_EQ(worst.element, 0u); // all equal: the lowest id
}

TEST(ResultEvaluator, TheWholeBoundaryEnclosesTheElementsDeformedVolume) {
  const model::Scene scene = block(0.3);
  const AssemblerWithHistory built(scene, world());
  assembly::Vector u(built.assembler->layout().ownedMap());
  deform(built.results, u);
  const std::vector<double> lambda(built.assembler->layout().numLocalElements(), 0.0);
  const std::vector<std::string> sides{"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  double enclosed = 0.0;
  for (double v : built.results.enclosedVolumes(u, sides)) enclosed += v;
  const assembly::ElementFields f = built.results.elementDilatations(u, lambda);
  double local = 0.0, elements = 0.0;
  for (std::size_t i = 0; i < f.theta.size(); ++i) local += f.theta[i] * f.referenceVolume[i];
  Teuchos::reduceAll(*world(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(elements));
  const double V = kSide * kSide * kSide;
  EXPECT_GT(std::abs(elements - V), 1e-4 * V); // the deformation changes the volume
  EXPECT_NEAR(enclosed, elements, 1e-13 * V);
}

TEST(ResultEvaluator, WithNoSurfaceLoadAClampedFacesResultantIsItsReaction) {
  const model::Scene scene = block(0.3);
  const AssemblerWithHistory built(scene, world());
  assembly::Vector u(built.assembler->layout().ownedMap());
  deform(built.results, u);
  built.assembler->applyDirichlet(u, 1.0);
  const std::vector<double> lambda(built.assembler->layout().numLocalElements(), 0.0);
  const auto reactions = built.results.reactions(u, 1.0, lambda);
  const auto resultants = built.results.faceSetResultants(u, 1.0, lambda, {"xmin"});
  ASSERT_EQ(reactions.size(), 1u);
  ASSERT_EQ(resultants.size(), 1u);
  const Eigen::Vector3d &R = reactions[0].force;
  EXPECT_GT(R.norm(), 0.0);
  EXPECT_LT((resultants[0] - R).norm(), 1e-12 * R.norm());
  EXPECT_EQ(reactions[0].power, 0.0); // a clamp at rest does no work
}
