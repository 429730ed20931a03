// The Contact section parsed into the scene's rigid contacts: each obstacle built with the deck's
// geometry (checked through the gap it reports), the penalty, search radius and contact points;
// a missing penalty or radius and a zero normal or axis refused with the file, line and parameter;
// a triangulated surface read beside the deck and turned to the body's side; nodes that start
// inside an obstacle deeper than the deck tolerates refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

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

// The deck's own end time, a ramp's default duration.
constexpr double kEndTime = 2.0;

model::Scene sceneOf(const std::string &file, const std::string &contacts) {
  model::Scene scene;
  buildContacts(test::deckOnFile(file, "<ParameterList name=\"Contact\">\n" + contacts + "</ParameterList>\n", schema()),
                kBox, kEndTime, scene);
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


// A square sheet at z = -0.25 (two triangles) written beside the deck and wound so that its
// normal points down (-z), away from the unit box above it: turned toward the body point, the
// box's bottom corner has the gap 0.25; as stored, -0.25, and with no tolerance it is refused.
void writeSheet(const std::string &name) {
  std::ofstream(test::deckPath(name)) << "# a square, wound clockwise seen from +z\n"
                                         "v -1 -1 -0.25\nv 2 -1 -0.25\nv 2 2 -0.25\nv -1 2 -0.25\n"
                                         "f 1 3 2\nf 1 4 3\n";
}

const char *kSheet = R"X(  <ParameterList name="sheet">
    <Parameter name="face set" type="string" value="zmin"/>
    <Parameter name="obstacle" type="string" value="surface"/>
    <Parameter name="file" type="string" value="contact_sheet.obj"/>
    <Parameter name="penalty" type="double" value="1e9"/>
)X";

TEST(ContactParameters, SurfaceObstacleFromAFileBesideTheDeck) {
  writeSheet("contact_sheet.obj");
  const model::Scene scene = sceneOf("contact_surface.xml", std::string(kSheet) + R"X(
    <Parameter name="normals" type="string" value="toward point"/>
    <Parameter name="body point" type="Array(double)" value="{0.5, 0.5, 0.5}"/>
  </ParameterList>
)X");
  ASSERT_EQ(scene.contacts.size(), 1u);
  const auto p = scene.contacts[0].obstacle->closest(Eigen::Vector3d::Zero(), 1.0);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->gap, 0.25, 1e-15);
  EXPECT_NEAR(p->normal.z(), 1.0, 1e-15);
}

TEST(ContactParameters, NodesStartingInsideTheObstacleAreRefusedByName) {
  writeSheet("contact_sheet.obj");
  // As stored, the sheet faces away from the box: all 9 bottom nodes are 0.25 "inside" it.
  const std::string asStored = std::string(kSheet) + "  </ParameterList>\n";
  EXPECT_EQ(errorOf("contact_inside.xml", asStored),
            "deck " + test::deckPath("contact_inside.xml") +
                ":3: parameter 'Contact/sheet': 9 node(s) of face set 'zmin' start inside the obstacle deeper than "
                "'start overlap tolerance' (0 m); deepest: node 0 at 0.25 m node 1 at 0.25 m node 2 at 0.25 m "
                "node 3 at 0.25 m node 4 at 0.25 m. Move the obstacle, raise the tolerance, or leave those faces out "
                "of the face set");
  // Within the tolerance it is taken.
  const model::Scene tolerated = sceneOf("contact_tolerated.xml", std::string(kSheet) + R"X(
    <Parameter name="start overlap tolerance" type="double" value="0.3"/>
  </ParameterList>
)X");
  EXPECT_NEAR(tolerated.contacts[0].obstacle->closest(Eigen::Vector3d::Zero(), 1.0)->gap, -0.25, 1e-15);
  // No file named.
  EXPECT_EQ(errorOf("contact_no_file.xml", R"X(  <ParameterList name="s">
    <Parameter name="face set" type="string" value="zmin"/>
    <Parameter name="obstacle" type="string" value="surface"/>
    <Parameter name="penalty" type="double" value="1e9"/>
  </ParameterList>
)X"),
            "deck " + test::deckPath("contact_no_file.xml") +
                ":3: parameter 'Contact/s': no 'file' given; a surface obstacle needs its OBJ or STL file");
}

}  // namespace
// Friction from the deck (the tangential penalty defaults to the penalty; tied), and a moving
// plane: the floor 0.5 below the origin rises by 0.4 along a ramp over the end time (2 s) and turns
// by 0.1 rad about y through the origin along a table reaching 1 at t = 1. At t = 1 the plane's
// point is R (0, 0, -0.5) + (0, 0, 0.2) and its normal R e_z = (sin 0.1, 0, cos 0.1), so the
// origin's gap is 0.5 - 0.2 cos 0.1.
TEST(ContactParameters, FrictionAndAMovingPlaneFromTheDeck) {
  const model::Scene scene = sceneOf("contact_motion.xml", R"X(  <ParameterList name="floor">
    <Parameter name="face set" type="string" value="zmin"/>
    <Parameter name="point" type="Array(double)" value="{0, 0, -0.5}"/>
    <Parameter name="penalty" type="double" value="1e9"/>
    <Parameter name="friction coefficient" type="double" value="0.3"/>
    <Parameter name="translation" type="Array(double)" value="{0, 0, 0.4}"/>
    <Parameter name="rotation axis" type="Array(double)" value="{0, 1, 0}"/>
    <Parameter name="rotation angle" type="double" value="0.1"/>
    <ParameterList name="rotation time function">
      <Parameter name="type" type="string" value="table"/>
      <Parameter name="times" type="Array(double)" value="{0, 1}"/>
      <Parameter name="values" type="Array(double)" value="{0, 1}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="glue">
    <Parameter name="face set" type="string" value="zmax"/>
    <Parameter name="point" type="Array(double)" value="{0, 0, 2}"/>
    <Parameter name="normal" type="Array(double)" value="{0, 0, -1}"/>
    <Parameter name="penalty" type="double" value="1e8"/>
    <Parameter name="friction" type="string" value="tied"/>
  </ParameterList>
)X");
  ASSERT_EQ(scene.contacts.size(), 2u);
  const auto &floor = scene.contacts[0], &glue = scene.contacts[1];
  EXPECT_EQ(floor.settings.friction.law, contact::FrictionLaw::coulomb);
  EXPECT_EQ(floor.settings.friction.coefficient, 0.3);
  EXPECT_EQ(floor.settings.friction.penalty, 1e9);
  EXPECT_EQ(glue.settings.friction.law, contact::FrictionLaw::tied);
  EXPECT_EQ(glue.motion, nullptr);
  ASSERT_NE(floor.motion, nullptr);
  EXPECT_DOUBLE_EQ(floor.obstacle->closest(Eigen::Vector3d::Zero(), 1.0)->gap, 0.5);
  floor.motion->setTime(1.0);
  EXPECT_NEAR(floor.obstacle->closest(Eigen::Vector3d::Zero(), 1.0)->gap, 0.5 - 0.2 * std::cos(0.1), 1e-15);
}

}  // namespace glossa::input
