// The Point section of glossa point parsed into its struct: the declared defaults, given values
// (directions made unit vectors, the table read row-major), and each deck it refuses, with the
// file, line and parameter the message names.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "DeckOnFile.hpp"
#include "input/PointParameters.hpp"

namespace glossa::input {
namespace {

Teuchos::ParameterList schema() {
  Teuchos::ParameterList s("Glossa");
  s.set("Point", pointParameters());
  return s;
}

PointParameters parsed(const std::string &name, const std::string &point, double endTime = 2.0) {
  return parsePointParameters(test::deckOnFile(name, point, schema()), endTime);
}

std::string refusal(const std::string &name, const std::string &point) {
  const io::Deck deck = test::deckOnFile(name, point, schema());
  return test::deckErrorOf([&] { parsePointParameters(deck, 1.0); });
}

TEST(PointParameters, DefaultsAreAUniaxialRampOverTheEndTime) {
  const PointParameters p = parsed("point_defaults.xml", "");
  EXPECT_EQ(p.path, PointPath::uniaxial);
  EXPECT_EQ(p.direction, Eigen::Vector3d::UnitX());
  EXPECT_EQ(p.shearPlaneNormal, Eigen::Vector3d::UnitY());
  EXPECT_EQ(p.amplitude, 0.2);
  EXPECT_EQ(p.position, Eigen::Vector3d::Zero());
  // The time function's default is a ramp whose duration is the run's end time (2 s here).
  EXPECT_DOUBLE_EQ(p.scale(0.5), 0.25);
  EXPECT_DOUBLE_EQ(p.scale(2.0), 1.0);
  EXPECT_TRUE(p.times.empty());
  EXPECT_TRUE(p.table.empty());
}

TEST(PointParameters, GivenValuesWithDirectionsMadeUnitVectors) {
  const PointParameters p = parsed("point_shear.xml", R"X(<ParameterList name="Point">
  <Parameter name="path" type="string" value="simple shear"/>
  <Parameter name="direction" type="Array(double)" value="{0, 0, 2}"/>
  <Parameter name="shear plane normal" type="Array(double)" value="{3, 0, 0}"/>
  <Parameter name="amplitude" type="double" value="0.5"/>
  <Parameter name="position" type="Array(double)" value="{0.01, 0.02, 0.03}"/>
  <ParameterList name="time function">
    <Parameter name="type" type="string" value="constant"/>
  </ParameterList>
</ParameterList>
)X");
  EXPECT_EQ(p.path, PointPath::simpleShear);
  EXPECT_EQ(p.direction, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(p.shearPlaneNormal, Eigen::Vector3d::UnitX());
  EXPECT_EQ(p.amplitude, 0.5);
  EXPECT_EQ(p.position, Eigen::Vector3d(0.01, 0.02, 0.03));
  EXPECT_EQ(p.scale(0.3), 1.0);
}

TEST(PointParameters, TableRowsAreRowMajor) {
  const PointParameters p = parsed("point_table.xml", R"X(<ParameterList name="Point">
  <Parameter name="path" type="string" value="table"/>
  <Parameter name="times" type="Array(double)" value="{0, 0.5}"/>
  <Parameter name="F" type="Array(double)" value="{1, 0, 0, 0, 1, 0, 0, 0, 1, 1.1, 0.2, 0, 0, 1, 0, 0, 0, 0.9}"/>
</ParameterList>
)X");
  EXPECT_EQ(p.path, PointPath::table);
  ASSERT_EQ(p.times, (std::vector<double>{0.0, 0.5}));
  ASSERT_EQ(p.table.size(), 2u);
  EXPECT_EQ(p.table[0], Eigen::Matrix3d::Identity());
  EXPECT_EQ(p.table[1](0, 0), 1.1);
  EXPECT_EQ(p.table[1](0, 1), 0.2); // F12: the second value of the row
  EXPECT_EQ(p.table[1](1, 0), 0.0);
  EXPECT_EQ(p.table[1](2, 2), 0.9);
}

TEST(PointParameters, AZeroDirectionIsRefusedWithItsLine) {
  EXPECT_EQ(refusal("point_zero_direction.xml", R"X(<ParameterList name="Point">
  <Parameter name="direction" type="Array(double)" value="{0, 0, 0}"/>
</ParameterList>
)X"),
            "deck " + test::deckPath("point_zero_direction.xml") + ":3: parameter 'Point/direction' is zero");
}

TEST(PointParameters, AShearPlaneNormalAlongTheDirectionIsRefused) {
  EXPECT_EQ(refusal("point_oblique_normal.xml", R"X(<ParameterList name="Point">
  <Parameter name="path" type="string" value="simple shear"/>
  <Parameter name="shear plane normal" type="Array(double)" value="{1, 1, 0}"/>
</ParameterList>
)X"),
            "deck " + test::deckPath("point_oblique_normal.xml") +
                ":4: parameter 'Point/shear plane normal' must be non-zero and orthogonal to 'direction'");
  // Uniaxial stretch has no shear plane: the same normal is not checked.
  EXPECT_EQ(refusal("point_uniaxial_normal.xml", R"X(<ParameterList name="Point">
  <Parameter name="shear plane normal" type="Array(double)" value="{1, 1, 0}"/>
</ParameterList>
)X"),
            "");
}

TEST(PointParameters, ATableIsRefusedForItsSizeItsTimesAndAnInvertedRow) {
  EXPECT_EQ(refusal("point_table_size.xml", R"X(<ParameterList name="Point">
  <Parameter name="path" type="string" value="table"/>
  <Parameter name="times" type="Array(double)" value="{0, 1}"/>
  <Parameter name="F" type="Array(double)" value="{1, 0, 0, 0, 1, 0, 0, 0, 1}"/>
</ParameterList>
)X"),
            "deck " + test::deckPath("point_table_size.xml") +
                ":5: parameter 'Point/F': needs 9 values per entry of 'times' (2 times, 9 values)");
  EXPECT_EQ(refusal("point_table_times.xml", R"X(<ParameterList name="Point">
  <Parameter name="path" type="string" value="table"/>
  <Parameter name="times" type="Array(double)" value="{0, 0}"/>
  <Parameter name="F" type="Array(double)" value="{1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1}"/>
</ParameterList>
)X"),
            "deck " + test::deckPath("point_table_times.xml") + ":4: parameter 'Point/times' must increase strictly");
  // Row 1 mirrors x: det F = -1.
  EXPECT_EQ(refusal("point_table_inverted.xml", R"X(<ParameterList name="Point">
  <Parameter name="path" type="string" value="table"/>
  <Parameter name="times" type="Array(double)" value="{0, 1}"/>
  <Parameter name="F" type="Array(double)" value="{1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, 1, 0, 0, 0, 1}"/>
</ParameterList>
)X"),
            "deck " + test::deckPath("point_table_inverted.xml") + ":5: parameter 'Point/F': row 1 has det F <= 0");
}

TEST(PointParameters, AValueGivenByTheCommandLineIsNamedAsSuch) {
  const io::Deck deck = test::deckOnFile("point_set.xml", "", schema(), {"Point/direction=0,0,0"});
  EXPECT_EQ(test::deckErrorOf([&] { parsePointParameters(deck, 1.0); }),
            "deck " + test::deckPath("point_set.xml") + " (--set on the command line): parameter 'Point/direction' is zero");
}

} // namespace
} // namespace glossa::input
