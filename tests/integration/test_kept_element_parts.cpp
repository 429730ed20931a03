// The assembler keeps each element's displacement part for the next pass at the same state
// (assembly/ElementPartCache). On the §7.2 block (two muscle groups, Hill fibres): an assembler
// that keeps parts against one that evaluates every pass afresh, through what may change between
// two passes at one displacement: nothing, the multipliers, a group's activation, the committed
// history, a new step. Each pass's residual and tangent must be the fresh assembler's to the local
// contractile solves' tolerance (they start from their last roots, 1e-14 of lambda_c), and a part
// kept under a stale key would be off by the change's own size (checked to be large).
#include <gtest/gtest.h>

#include "MuscleBlockScene.hpp"
#include "RunDeck.hpp"
#include "assembly/Assembler.hpp"
#include "assembly/MuscleResponse.hpp"
#include "assembly/ResultEvaluator.hpp"
#include "input/SceneFactory.hpp"

using namespace glossa;

namespace {

struct Side {
  Side(const model::Scene &scene, bool keep)
      : layout(assembly::distributeScene(scene, Tpetra::getDefaultComm())), history(scene.muscles, layout.localElements),
        assembler(scene, layout, history, Tpetra::getDefaultComm(), nullptr,
                  keep ? assembly::ElementParts::Kept : assembly::ElementParts::Fresh),
        K(assembler.createMatrix()), f(assembler.layout().ownedMap()) {}
  // Residual and tangent at (u, lambda).
  void assemble(const assembly::Vector &u, const std::vector<double> &lambda) {
    const auto status = assembler.assemble(u, 0.05, lambda, nullptr, &f, K.get());
    ASSERT_TRUE(status.valid);
  }
  assembly::DofLayout layout;
  model::MuscleHistory history;
  assembly::Assembler assembler;
  Teuchos::RCP<assembly::FEMatrix> K;
  assembly::Vector f;
};

// |a - b| for two residuals and two tangents on the same graph, relative to b's.
double residualDifference(const Side &a, const Side &b) {
  assembly::Vector d(b.f.getMap());
  d.update(1.0, a.f, -1.0, b.f, 0.0);
  return d.norm2() / b.f.norm2();
}
double tangentDifference(const Side &a, const Side &b) {
  const auto va = a.K->getLocalMatrixHost().values, vb = b.K->getLocalMatrixHost().values;
  double diff = 0.0, size = 0.0;
  for (std::size_t k = 0; k < vb.extent(0); ++k) {
    diff += (va(k) - vb(k)) * (va(k) - vb(k));
    size += vb(k) * vb(k);
  }
  return std::sqrt(diff / size);
}

} // namespace

TEST(KeptElementParts, EveryPassEqualsAFreshOneWhateverChangedBetween) {
  const model::Scene scene = test::smallMuscleBlockScene();
  Side kept(scene, true), fresh(scene, false);
  const int groups = static_cast<int>(scene.muscles.groups.size());
  ASSERT_GE(groups, 2);
  std::vector<double> inputs;
  for (int g = 0; g < groups; ++g) inputs.push_back(0.3 + 0.2 * g);
  for (Side *s : {&kept, &fresh}) s->history.beginStep(0.05, 0.05, inputs);

  // A stretch with a shear, so that the fibres carry tension.
  std::vector<double> all(3 * scene.mesh.numNodes());
  for (std::size_t n = 0; n < scene.mesh.numNodes(); ++n) {
    const Eigen::Vector3d &X = scene.mesh.nodes[n];
    all[3 * n] = 0.02 * X(0) + 0.01 * X(1), all[3 * n + 1] = -0.01 * X(1), all[3 * n + 2] = -0.01 * X(2);
  }
  assembly::Vector u(kept.assembler.layout().ownedMap());
  assembly::ResultEvaluator(kept.assembler).scatterDisplacement(all, u);
  std::vector<double> lambda(kept.assembler.layout().numLocalElements(), 0.0);

  const double tolerance = 1e-12;
  auto expectSame = [&](const char *what) {
    kept.assemble(u, lambda);
    fresh.assemble(u, lambda);
    EXPECT_LT(residualDifference(kept, fresh), tolerance) << what;
    EXPECT_LT(tangentDifference(kept, fresh), tolerance) << what;
  };
  // What the last fresh pass gave, to show that each change moves the pass by far more than the
  // tolerance (a stale part would be caught).
  assembly::Vector lastF(fresh.f, Teuchos::Copy);
  auto expectMoved = [&](const char *what) {
    assembly::Vector d(fresh.f.getMap());
    d.update(1.0, fresh.f, -1.0, lastF, 0.0);
    EXPECT_GT(d.norm2(), 1e-6 * fresh.f.norm2()) << what << " does not change the residual";
    lastF.assign(fresh.f);
  };

  expectSame("the first pass");
  lastF.assign(fresh.f);
  // The repeated pass evaluates only the passive elements again (they keep no part).
  std::uint64_t muscleElements = 0;
  for (const int region : scene.muscles.elementRegion) muscleElements += region >= 0;
  ASSERT_GT(muscleElements, 0u);
  const std::uint64_t evaluated = kept.assembler.elementPartCounts().evaluated;
  expectSame("the same state again");
  EXPECT_EQ(kept.assembler.elementPartCounts().reused, muscleElements);
  EXPECT_EQ(kept.assembler.elementPartCounts().evaluated, 2 * evaluated - muscleElements);

  for (std::size_t i = 0; i < lambda.size(); ++i) lambda[i] = 2e3 * static_cast<double>(i % 5 + 1);
  expectSame("other multipliers");
  expectMoved("the multipliers");

  for (Side *s : {&kept, &fresh}) s->history.setTrialActivation(1, s->history.groupActivation(1) + 0.2);
  expectSame("another activation of group 1");
  expectMoved("group 1's activation");

  // The step's lambda_c at u committed, then the next step at the same activations and step
  // size: only the committed history the point laws read has moved.
  for (Side *s : {&kept, &fresh}) {
    const std::vector<double> alpha = s->history.trialActivation();
    assembly::updateMuscleHistory(assembly::ResultEvaluator(s->assembler), u, s->history);
    s->history.commit();
    s->history.beginStep(0.1, 0.05, inputs);
    for (int g = 0; g < groups; ++g) s->history.setTrialActivation(g, alpha[static_cast<std::size_t>(g)]);
  }
  expectSame("the next step");
  expectMoved("the committed history");
}

// A passive scene keeps no part (a cheap law is not worth 11 KB an element): a repeated pass at
// the same state evaluates every element again.
TEST(KeptElementParts, APassiveSceneKeepsNothing) {
  const auto schema = app::deckSchema();
  auto deck = io::Deck::fromFile(test::inputPath("verification/step44_block.xml"));
  deck.applyOverride("Mesh/Box/cells={2,2,2}", schema);
  deck.validate(schema);
  const model::Scene scene = input::buildScene(deck, 1.0);
  Side side(scene, true);
  assembly::Vector u(side.assembler.layout().ownedMap());
  u.putScalar(1e-3);
  const std::vector<double> lambda(side.assembler.layout().numLocalElements(), 0.0);
  side.assemble(u, lambda);
  side.assemble(u, lambda);
  EXPECT_EQ(side.assembler.elementPartCounts().reused, 0u);
  EXPECT_EQ(side.assembler.elementPartCounts().evaluated, 2 * side.assembler.layout().numLocalElements());
}
