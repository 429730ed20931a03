// A deformable pair through the distributed assembly (assembly/ContactEvaluation), on 1 rank and
// under mpiexec on 2: two blocks in one mesh, 2 x 2 cells under 3 x 3, the upper pressed into the
// lower and sheared. The assembled tangent is the central difference of the assembled residual,
// master rows and columns included: an entry the graph lacked would be dropped by the matrix and
// show here. The state's measures at the same state see the points that carry pressure.
#include <gtest/gtest.h>

#include <cmath>

#include "../contact/StackedBoxes.hpp"
#include "BlockFixture.hpp"
#include "assembly/ContactResponse.hpp"
#include "contact/DeformablePair.hpp"

using namespace glossa;
using namespace glossa::assembly::testing;

namespace {

// The blocks of side kSide, the lower one clamped at its bottom, the upper one's bottom in
// contact with the lower one's top (penalty, segments or 2 x 2 Gauss points).
model::Scene pairedBlocks(contact::SlaveRule rule) {
  model::Scene scene = block(0.3);
  scene.mesh = test::stackedBoxes(kSide, {2, 2, 1}, {3, 3, 1}, 0.0);
  scene.bodyForces.clear();
  scene.dirichlet.front().nodes = scene.mesh.nodeSets.at("zmin");
  model::RigidContact pair;
  pair.name = "interface";
  pair.faces = scene.mesh.faceSets.at("upper bottom");
  pair.settings.penalty = 1e8;
  pair.settings.searchRadius = 0.2 * kSide;
  pair.enforcement = model::ContactEnforcement::penalty;
  pair.pair = std::make_shared<const contact::DeformablePair>(
      contact::pairFaces(scene.mesh, pair.faces, scene.mesh.faceSets.at("lower top"), false,
                         pair.settings.searchRadius, 0.5 * kSide, rule, 2));
  pair.state = std::make_shared<contact::ContactState>(pair.faces.size(), pair.pair->pointsPerFace());
  scene.contacts.push_back(pair);
  scene.symmetricTangent = false;
  return scene;
}

// The upper block pushed 1 % of the side into the lower one, sheared and stretched.
void press(const assembly::ResultEvaluator &results, assembly::Vector &u) {
  const auto &nodes = results.scene().mesh.nodes;
  std::vector<double> all(3 * nodes.size(), 0.0);
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const Eigen::Vector3d X = nodes[n] / kSide;
    const bool upper = n >= 18;  // the lower block's 3 x 3 x 2 nodes come first
    all[3 * n] = 0.01 * kSide * X.z() * X.y();
    all[3 * n + 1] = 0.005 * kSide * X.x();
    all[3 * n + 2] = (upper ? -0.01 : 0.002 * X.x()) * kSide * X.z();
  }
  results.scatterDisplacement(all, u);
}

void expectTangentAndMeasures(contact::SlaveRule rule) {
  const model::Scene scene = pairedBlocks(rule);
  const AssemblerWithHistory built(scene, world());
  const assembly::Assembler &assembler = *built.assembler;
  assembly::Vector u(assembler.layout().ownedMap());
  press(built.results, u);
  assembler.applyDirichlet(u, 1.0);
  std::vector<double> all(3 * scene.mesh.nodes.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = 1e-5 * kSide * std::sin(1.3 * static_cast<double>(k) + 0.7);
  const TangentCheck check = centralDifferenceCheck(assembler, built.results, u, all, 1e-2);
  EXPECT_GT(check.scale, 0.0);
  EXPECT_LT(check.error, 1e-6 * check.scale) << "|Kv| = " << check.scale;
  // Every point was evaluated at u: the state records the pressures (some points carry them).
  const auto measures = assembly::updateContactStates(built.results, u);
  ASSERT_EQ(measures.size(), 1u);
  EXPECT_GT(measures[0].activePoints, 0);
  EXPECT_GT(measures[0].normalForce, 0.0);
}

}  // namespace

TEST(ContactEvaluation, PairTangentIsTheCentralDifferenceOfTheResidualWithSegments) {
  expectTangentAndMeasures(contact::SlaveRule::segments);
}
TEST(ContactEvaluation, PairTangentIsTheCentralDifferenceOfTheResidualWithGaussPoints) {
  expectTangentAndMeasures(contact::SlaveRule::gauss);
}
