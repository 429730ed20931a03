// The Zero strain section of glossa zero-strain parsed into its struct (defaults and given
// values), and what the command asks of the rest of the deck: the mesh as read, loaded by gravity
// alone; each refusal names the file, line and parameter.
#include <gtest/gtest.h>

#include "DeckOnFile.hpp"
#include "input/ZeroStrainParameters.hpp"
#include "io/deck/ParameterSpec.hpp"

namespace glossa::input {
namespace {

// The Zero strain section, and of the Mesh and Loads sections what the messages name.
Teuchos::ParameterList schema() {
  Teuchos::ParameterList s("Glossa");
  s.set("Zero strain", zeroStrainParameters());
  io::declareString(s.sublist("Mesh"), "reference coordinates file", "", "the zero-strain configuration");
  Teuchos::ParameterList load;
  io::declareString(load, "type", "gravity", "the load", {"gravity", "body force", "dead traction", "follower pressure"});
  s.sublist("Loads").set(io::kAnySublist, load);
  return s;
}

// Lines 2-9: a gravity load "weight" (its type on line 4) and a dead traction "push" (line 7).
const char *kLoads = R"X(<ParameterList name="Loads">
  <ParameterList name="weight">
    <Parameter name="type" type="string" value="gravity"/>
  </ParameterList>
  <ParameterList name="push">
    <Parameter name="type" type="string" value="dead traction"/>
  </ParameterList>
</ParameterList>
)X";

model::BodyForceLoad gravity(const std::string &name) {
  model::BodyForceLoad g;
  g.name = name;
  g.gravity = true;
  return g;
}

TEST(ZeroStrainParameters, DefaultsAreTheInverseToAThousandthOfTheEdge) {
  const ZeroStrainParameters z = parseZeroStrainParameters(test::deckOnFile("zero_strain_defaults.xml", "", schema()));
  EXPECT_EQ(z.method, ZeroStrainMethod::inverse);
  EXPECT_EQ(z.gravityFactor, 1.2);
  EXPECT_EQ(z.tolerance, 1e-3);
  EXPECT_EQ(z.maximumIterations, 10);
}

TEST(ZeroStrainParameters, GivenValues) {
  const ZeroStrainParameters z = parseZeroStrainParameters(test::deckOnFile("zero_strain_values.xml",
                                                                            R"X(<ParameterList name="Zero strain">
  <Parameter name="method" type="string" value="approximate"/>
  <Parameter name="gravity factor" type="double" value="1.5"/>
  <Parameter name="tolerance" type="double" value="0.01"/>
</ParameterList>
)X",
                                                                            schema(), {"Zero strain/maximum iterations=4"}));
  EXPECT_EQ(z.method, ZeroStrainMethod::approximate);
  EXPECT_EQ(z.gravityFactor, 1.5);
  EXPECT_EQ(z.tolerance, 0.01);
  EXPECT_EQ(z.maximumIterations, 4);
}

TEST(ZeroStrainParameters, AMeshAsReadUnderGravityAloneIsAccepted) {
  const io::Deck deck = test::deckOnFile("zero_strain_gravity.xml", "", schema());
  model::Scene scene;
  scene.bodyForces = {gravity("weight"), gravity("more weight")};
  EXPECT_EQ(test::deckErrorOf([&] { requireImagedGeometryUnderGravity(deck, scene); }), "");
}

TEST(ZeroStrainParameters, AnyOtherLoadIsRefusedByName) {
  const io::Deck deck = test::deckOnFile("zero_strain_loads.xml", kLoads, schema());
  const std::string at = "deck " + test::deckPath("zero_strain_loads.xml");
  const std::string why = ": glossa zero-strain needs a deck loaded by gravity alone (the configuration gravity maps "
                          "onto the imaged geometry); ";
  model::Scene scene;
  scene.bodyForces = {gravity("weight")};
  scene.tractions.resize(1);
  scene.tractions[0].name = "push";
  EXPECT_EQ(test::deckErrorOf([&] { requireImagedGeometryUnderGravity(deck, scene); }),
            at + ":7: parameter 'Loads/push/type'" + why + "'push' is a dead traction load");
  scene.tractions.clear();
  scene.pressures.resize(1);
  scene.pressures[0].name = "push";
  EXPECT_EQ(test::deckErrorOf([&] { requireImagedGeometryUnderGravity(deck, scene); }),
            at + ":7: parameter 'Loads/push/type'" + why + "'push' is a follower pressure load");
  scene.pressures.clear();
  scene.bodyForces[0].gravity = false;
  EXPECT_EQ(test::deckErrorOf([&] { requireImagedGeometryUnderGravity(deck, scene); }),
            at + ":4: parameter 'Loads/weight/type'" + why + "'weight' is a body force load");
}

TEST(ZeroStrainParameters, NoLoadAtAllIsRefused) {
  const io::Deck deck = test::deckOnFile("zero_strain_unloaded.xml", "", schema());
  EXPECT_EQ(test::deckErrorOf([&] { requireImagedGeometryUnderGravity(deck, model::Scene()); }),
            "deck " + test::deckPath("zero_strain_unloaded.xml") +
                ": parameter 'Loads': glossa zero-strain needs at least one gravity load");
}

TEST(ZeroStrainParameters, AReferenceCoordinatesFileIsRefused) {
  const io::Deck deck = test::deckOnFile("zero_strain_reference.xml", R"X(<ParameterList name="Mesh">
  <Parameter name="reference coordinates file" type="string" value="x0.txt"/>
</ParameterList>
)X",
                                         schema());
  model::Scene scene;
  scene.bodyForces = {gravity("weight")};
  scene.mesh.imagedNodes = {Eigen::Vector3d::Zero()}; // what the file sets
  EXPECT_EQ(test::deckErrorOf([&] { requireImagedGeometryUnderGravity(deck, scene); }),
            "deck " + test::deckPath("zero_strain_reference.xml") +
                ":3: parameter 'Mesh/reference coordinates file': glossa zero-strain starts from the mesh as read "
                "(the imaged geometry); leave it empty");
}

} // namespace
} // namespace glossa::input
