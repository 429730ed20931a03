// The checks across sections that glossa validate and glossa run share (solvers/parameters/
// RunChecks), on a deck of the solver's sections and a scene built in code: each refusal names
// its parameter (file and line where the deck has them) and what is allowed instead, a sound
// configuration passes, and a direct solve names the iterative settings it leaves unused.
#include <gtest/gtest.h>

#include <limits>

#include "DeckOnFile.hpp"
#include "materials/NeoHookean.hpp"
#include "mesh/BoxGenerator.hpp"
#include "model/Scene.hpp"
#include "solvers/parameters/ControlSection.hpp"
#include "solvers/parameters/RunChecks.hpp"

namespace glossa::solvers {
namespace {

Teuchos::ParameterList schema() {
  Teuchos::ParameterList s("Glossa");
  declareSolverParameters(s);
  return s;
}

// A block of one tissue (two when asked), nu as given, its x = 0 face held still.
model::Scene block(double nu, int tissues = 1) {
  model::Scene scene;
  scene.mesh = mesh::generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(1e-2), {2, 1, 1});
  for (int t = 0; t < tissues; ++t) {
    model::Tissue tissue;
    tissue.name = "tissue " + std::to_string(t);
    tissue.matrix = std::make_shared<materials::NeoHookean>(1e4);
    tissue.volumetric = materials::VolumetricEnergy(materials::VolumetricEnergy::Form::SimoTaylor,
                                                    nu == 0.5 ? std::numeric_limits<double>::infinity()
                                                              : materials::bulkModulus(1e4, nu));
    scene.tissues.push_back(tissue);
  }
  if (tissues > 1) scene.elementTissue = {0, 1};
  model::DirichletCondition held;
  held.name = "held";
  held.nodes = scene.mesh.nodeSets.at("xmin");
  held.fixed = {true, true, true};
  scene.dirichlet.push_back(held);
  return scene;
}

struct Case {
  io::Deck deck;
  RunConfiguration config;
};

Case deckWith(const std::string &name, const std::string &sections) {
  io::Deck deck = test::deckOnFile(name, sections, schema());
  return {deck, parseRunConfiguration(deck)};
}

std::string refusal(const Case &c, const model::Scene &scene, const RunCheckContext &context = {}) {
  return test::deckErrorOf([&] { checkRunConfiguration(c.deck, c.config, scene, ControlSetup{}, context); });
}
} // namespace

TEST(RunChecks, ASoundConfigurationPasses) {
  const Case c = deckWith("sound.xml", "");
  EXPECT_EQ(refusal(c, block(0.4999)), "");
  EXPECT_EQ(refusal(c, block(0.5)), ""); // the augmented Lagrangian holds nu = 0.5
}

TEST(RunChecks, APenaltyCannotHoldNuOneHalf) {
  const Case c = deckWith("penalty.xml", R"X(<ParameterList name="Incompressibility">
  <Parameter name="method" type="string" value="penalty"/>
</ParameterList>
)X");
  EXPECT_EQ(refusal(c, block(0.4999)), "");
  EXPECT_NE(refusal(c, block(0.5)).find("needs Incompressibility/method = augmented Lagrangian or mixed"),
            std::string::npos);
}

TEST(RunChecks, ArcLengthNeedsThePenaltyMethodAndSaysWhere) {
  const Case c = deckWith("arc_length.xml", R"X(<ParameterList name="Time">
  <Parameter name="path following" type="string" value="arc length"/>
</ParameterList>
)X");
  const std::string why = refusal(c, block(0.4999));
  EXPECT_NE(why.find("arc_length.xml:3"), std::string::npos) << why;
  EXPECT_NE(why.find("Time/path following"), std::string::npos) << why;
  EXPECT_NE(why.find("arc-length continuation needs Incompressibility/method = penalty"), std::string::npos) << why;
  const Case follow = deckWith("follow.xml", R"X(<ParameterList name="Time">
  <Parameter name="at a limit point" type="string" value="follow"/>
</ParameterList>
<ParameterList name="Incompressibility">
  <Parameter name="method" type="string" value="penalty"/>
</ParameterList>
)X");
  EXPECT_EQ(refusal(follow, block(0.4999)), "");
  model::Scene moving = block(0.4999);
  moving.dirichlet[0].value = Eigen::Vector3d(1e-3, 0.0, 0.0);
  EXPECT_NE(refusal(follow, moving).find("Boundary conditions/held prescribes a displacement"), std::string::npos);
}

TEST(RunChecks, TheMixedMethodHoldsOneTissue) {
  const Case c = deckWith("mixed.xml", R"X(<ParameterList name="Incompressibility">
  <Parameter name="method" type="string" value="mixed"/>
</ParameterList>
)X");
  EXPECT_EQ(refusal(c, block(0.4999)), "");
  EXPECT_NE(refusal(c, block(0.4999, 2)).find("one tissue"), std::string::npos);
}

TEST(RunChecks, AnUnknownFaceSetOfTheOutputIsNamed) {
  const Case c = deckWith("faces.xml", R"X(<ParameterList name="Output">
  <Parameter name="volume face sets" type="string" value="xmax, nowhere"/>
</ParameterList>
)X");
  const std::string why = refusal(c, block(0.4999));
  EXPECT_NE(why.find("faces.xml:3"), std::string::npos) << why;
  EXPECT_NE(why.find("no face set 'nowhere'"), std::string::npos) << why;
}

TEST(RunChecks, ControlGroupsDivideTheRanksAndNeedTheGeneticAlgorithm) {
  const Case c = deckWith("groups.xml", "");
  EXPECT_NE(refusal(c, block(0.4999), {2, 3, false}).find("must be at least 1 and divide the number of ranks (2)"),
            std::string::npos);
  EXPECT_NE(refusal(c, block(0.4999), {2, 2, false}).find("needs Control/type = genetic algorithm"), std::string::npos);
  EXPECT_EQ(refusal(c, block(0.4999), {2, 1, false}), "");
}

TEST(RunChecks, ADirectSolveNamesTheIterativeSettingsItLeavesUnused) {
  const Case c = deckWith("direct.xml", R"X(<ParameterList name="Linear solver">
  <Parameter name="smoother degree" type="int" value="4"/>
</ParameterList>
)X");
  const auto warnings = ignoredIterativeSettings(c.config, true, 1234);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("direct.xml:3"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("1234 unknowns"), std::string::npos) << warnings[0];
  EXPECT_TRUE(ignoredIterativeSettings(c.config, false, 1234).empty());
}

} // namespace glossa::solvers
