// The Contact section parsed into the scene's rigid contacts: each obstacle built with the deck's
// geometry (checked through the gap it reports), the penalty, search radius and contact points;
// a missing penalty or radius and a zero normal or axis refused with the file, line and parameter.
#include <gtest/gtest.h>

#include <cmath>

#include "DeckOnFile.hpp"
#include "input/ContactParameters.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "mesh/BoxGenerator.hpp"

namespace glossa::input {
namespace {

Teuchos::ParameterList schema() {
  Teuchos::ParameterList s("Glossa");
  s.sublist("Contact").set(io::kAnySublist, contactParameters());
  return s;
}

const mesh::HexMesh kBox = mesh::generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {2, 2, 2});

model::Scene sceneOf(const std::string &file, const std::string &contacts) {
  model::Scene scene;
  buildContacts(test::deckOnFile(file, "<ParameterList name=\"Contact\">\n" + contacts + "</ParameterList>\n", schema()),
                kBox, scene);
  return scene;
}

std::string errorOf(const std::string &file, const std::string &contacts) {
  return test::deckErrorOf([&] { sceneOf(file, contacts); });
}

// A plane 0.5 below the body, a sphere and a cylinder of radius 2 whose surfaces pass through
// the origin: the origin's gaps are 0.5, 0 and 0.
TEST(ContactParameters, ObstaclesFromTheDeck) {
  const model::Scene scene = sceneOf("contact_obstacles.xml", R"X(  <ParameterList name="floor">
    <Parameter name="face set" type="string" value="zmin"/>
    <Parameter name="point" type="Array(double)" value="{0, 0, -0.5}"/>
    <Parameter name="normal" type="Array(double)" value="{0, 0, 3}"/>
    <Parameter name="penalty" type="double" value="1e9"/>
  </ParameterList>
  <ParameterList name="ball">
    <Parameter name="face set" type="string" value="xmin"/>
    <Parameter name="obstacle" type="string" value="sphere"/>
    <Parameter name="point" type="Array(double)" value="{-2, 0, 0}"/>
    <Parameter name="radius" type="double" value="2"/>
    <Parameter name="penalty" type="double" value="1e8"/>
    <Parameter name="search radius" type="double" value="0.1"/>
    <Parameter name="contact points" type="string" value="nodal"/>
  </ParameterList>
  <ParameterList name="roller">
    <Parameter name="face set" type="string" value="ymin"/>
    <Parameter name="obstacle" type="string" value="cylinder"/>
    <Parameter name="point" type="Array(double)" value="{0, -2, 5}"/>
    <Parameter name="axis" type="Array(double)" value="{0, 0, 1}"/>
    <Parameter name="radius" type="double" value="2"/>
    <Parameter name="penalty" type="double" value="1e8"/>
  </ParameterList>
)X");
  ASSERT_EQ(scene.contacts.size(), 3u);
  EXPECT_FALSE(scene.symmetricTangent);
  const auto &floor = scene.contacts[0], &ball = scene.contacts[1], &roller = scene.contacts[2];
  EXPECT_EQ(floor.name, "floor");
  EXPECT_EQ(floor.faces.size(), 4u);
  EXPECT_EQ(floor.settings.penalty, 1e9);
  EXPECT_EQ(floor.settings.searchRadius, 1.0);
  EXPECT_EQ(floor.settings.rule, contact::ContactQuadrature::gauss);
  EXPECT_DOUBLE_EQ(floor.obstacle->closest(Eigen::Vector3d::Zero(), 1.0)->gap, 0.5);
  EXPECT_EQ(ball.settings.rule, contact::ContactQuadrature::nodal);
  EXPECT_EQ(ball.settings.searchRadius, 0.1);
  EXPECT_NEAR(ball.obstacle->closest(Eigen::Vector3d::Zero(), 1.0)->gap, 0.0, 1e-15);
  EXPECT_NEAR(ball.obstacle->closest(Eigen::Vector3d(0, 0, 1), 1.0)->gap, std::sqrt(5.0) - 2, 1e-15);
  EXPECT_NEAR(roller.obstacle->closest(Eigen::Vector3d(0, 0, -7), 1.0)->gap, 0.0, 1e-15);
}

// Each refusal names the deck's file and line (the contact's sublist is line 3, its parameters
// from line 4; a parameter not given is named at its sublist).
TEST(ContactParameters, MissingPenaltyOrRadiusAndZeroVectorsAreRefused) {
  struct Case {
    const char *file, *contact, *error;
  };
  const Case cases[] = {
      {"contact_no_penalty.xml", R"X(<Parameter name="face set" type="string" value="zmin"/>)X",
       ":3: parameter 'Contact/c': no 'penalty' given; the penalty method needs a value > 0"},
      {"contact_zero_penalty.xml",
       R"X(<Parameter name="face set" type="string" value="zmin"/>
<Parameter name="penalty" type="double" value="0"/>)X",
       ":5: parameter 'Contact/c/penalty' is 0; the penalty method needs a value > 0"},
      {"contact_no_radius.xml",
       R"X(<Parameter name="face set" type="string" value="zmin"/>
<Parameter name="obstacle" type="string" value="sphere"/>
<Parameter name="penalty" type="double" value="1e8"/>)X",
       ":3: parameter 'Contact/c': no 'radius' given; a sphere needs a value > 0"},
      {"contact_zero_normal.xml",
       R"X(<Parameter name="face set" type="string" value="zmin"/>
<Parameter name="normal" type="Array(double)" value="{0, 0, 0}"/>
<Parameter name="penalty" type="double" value="1e8"/>)X",
       ":5: parameter 'Contact/c/normal': PlaneObstacle: the normal must be a finite nonzero vector"},
      {"contact_zero_axis.xml",
       R"X(<Parameter name="face set" type="string" value="zmin"/>
<Parameter name="obstacle" type="string" value="cylinder"/>
<Parameter name="axis" type="Array(double)" value="{0, 0, 0}"/>
<Parameter name="radius" type="double" value="1"/>
<Parameter name="penalty" type="double" value="1e8"/>)X",
       ":6: parameter 'Contact/c/axis': CylinderObstacle: the axis must be a finite nonzero vector"},
      {"contact_no_set.xml",
       R"X(<Parameter name="face set" type="string" value="bottom"/>
<Parameter name="penalty" type="double" value="1e8"/>)X",
       ":4: parameter 'Contact/c/face set': no face set 'bottom'; the mesh has: xmax, xmin, ymax, ymin, zmax, zmin"},
  };
  for (const Case &c : cases) {
    const std::string xml = std::string("<ParameterList name=\"c\">\n") + c.contact + "\n</ParameterList>\n";
    EXPECT_EQ(errorOf(c.file, xml), "deck " + test::deckPath(c.file) + c.error);
  }
}

}  // namespace
}  // namespace glossa::input
