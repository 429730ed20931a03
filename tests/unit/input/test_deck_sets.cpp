// The names a deck gives resolved against the mesh and the muscle groups: an element, face or
// node set, or a group, is found by its name; a name that does not exist is a DeckError with the
// file, line and parameter, and the names that do exist.
#include <gtest/gtest.h>

#include "DeckOnFile.hpp"
#include "input/DeckSets.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "mesh/BoxGenerator.hpp"

namespace glossa::input {
namespace {

Teuchos::ParameterList schema() {
  Teuchos::ParameterList s("Glossa"), load;
  for (const char *name : {"element set", "face set", "node set", "muscle group"})
    io::declareString(load, name, "", "a name the mesh or the Material section defines");
  s.sublist("Loads").set(io::kAnySublist, load);
  return s;
}

// Loads/known names what exists (lines 4-7), Loads/unknown what does not (lines 10-13).
io::Deck deck() {
  return test::deckOnFile("deck_sets.xml", R"X(<ParameterList name="Loads">
  <ParameterList name="known">
    <Parameter name="element set" type="string" value="all"/>
    <Parameter name="face set" type="string" value="xmax"/>
    <Parameter name="node set" type="string" value="zmin"/>
    <Parameter name="muscle group" type="string" value="GGp"/>
  </ParameterList>
  <ParameterList name="unknown">
    <Parameter name="element set" type="string" value="tongue"/>
    <Parameter name="face set" type="string" value="top"/>
    <Parameter name="node set" type="string" value="apex"/>
    <Parameter name="muscle group" type="string" value="HG"/>
  </ParameterList>
</ParameterList>
)X",
                          schema());
}

std::string at(int line) { return "deck " + test::deckPath("deck_sets.xml") + ":" + std::to_string(line) + ": "; }

const mesh::HexMesh kBox = mesh::generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), {2, 3, 4});

TEST(DeckSets, AStringIsReadAtItsPath) {
  EXPECT_EQ(deckString(deck(), {"Loads", "known", "face set"}), "xmax");
  EXPECT_EQ(deckString(deck(), {"Loads", "unknown", "muscle group"}), "HG");
}

TEST(DeckSets, ElementSetsByNameOrEveryElement) {
  const io::Deck d = deck();
  EXPECT_EQ(elementSetOrAll(d, kBox, {"Loads", "known", "element set"}), kBox.elementSets.at("all"));
  EXPECT_EQ(elementSetOrAll(d, kBox, {"Loads", "known", "element set"}).size(), 24u);
  EXPECT_EQ(test::deckErrorOf([&] { elementSetOrAll(d, kBox, {"Loads", "unknown", "element set"}); }),
            at(10) + "parameter 'Loads/unknown/element set': no element set 'tongue'; the mesh has: all");
  // An empty name: every element, in order.
  Teuchos::ParameterList list("Glossa");
  list.sublist("Loads").sublist("whole").set<std::string>("element set", "");
  const auto all = elementSetOrAll(io::Deck::fromList(list, "built"), kBox, {"Loads", "whole", "element set"});
  ASSERT_EQ(all.size(), 24u);
  for (std::size_t e = 0; e < all.size(); ++e) EXPECT_EQ(all[e], static_cast<mesh::ElementId>(e));
}

// A set of no element (an empty Abaqus ELSET, a Gmsh group of other elements) would make a
// tissue or fibre family of nothing: refused, whatever uses it.
TEST(DeckSets, AnEmptyElementSetIsRefused) {
  mesh::HexMesh m = kBox;
  m.elementSets["tongue"] = {};
  EXPECT_EQ(test::deckErrorOf([&] { elementSetOrAll(deck(), m, {"Loads", "unknown", "element set"}); }),
            at(10) + "parameter 'Loads/unknown/element set': element set 'tongue' has no elements");
}

TEST(DeckSets, FaceAndNodeSetsByName) {
  const io::Deck d = deck();
  EXPECT_EQ(faceSetAt(d, kBox, {"Loads", "known", "face set"}).size(), 12u); // 3 x 4 faces at x = 1
  EXPECT_EQ(nodeSetAt(d, kBox, {"Loads", "known", "node set"}).size(), 12u); // 3 x 4 nodes at z = 0
  EXPECT_EQ(test::deckErrorOf([&] { faceSetAt(d, kBox, {"Loads", "unknown", "face set"}); }),
            at(11) + "parameter 'Loads/unknown/face set': no face set 'top'; the mesh has: xmax, xmin, ymax, ymin, "
                     "zmax, zmin");
  EXPECT_EQ(test::deckErrorOf([&] { nodeSetAt(d, kBox, {"Loads", "unknown", "node set"}); }),
            at(12) + "parameter 'Loads/unknown/node set': no node set 'apex'; the mesh has: xmax, xmin, ymax, ymin, "
                     "zmax, zmin");
}

TEST(DeckSets, MuscleGroupsByNameOrNone) {
  const io::Deck d = deck();
  model::MuscleArchitecture muscles;
  muscles.groups.resize(2);
  muscles.groups[0].name = "GGa";
  muscles.groups[1].name = "GGp";
  EXPECT_EQ(muscleGroupAt(d, muscles, {"Loads", "known", "muscle group"}, true), 1);
  EXPECT_EQ(test::deckErrorOf([&] { muscleGroupAt(d, muscles, {"Loads", "unknown", "muscle group"}, false); }),
            at(13) + "parameter 'Loads/unknown/muscle group': no muscle group 'HG' in Material/Muscle groups (GGa, GGp)");
  EXPECT_EQ(test::deckErrorOf([&] { muscleGroupAt(d, {}, {"Loads", "unknown", "muscle group"}, false); }),
            at(13) + "parameter 'Loads/unknown/muscle group': no muscle group 'HG' in Material/Muscle groups (none "
                     "declared)");
  // An empty name: no group, unless one is required.
  Teuchos::ParameterList list("Glossa");
  list.sublist("Loads").sublist("passive").set<std::string>("muscle group", "");
  const io::Deck unnamed = io::Deck::fromList(list, "built");
  EXPECT_EQ(muscleGroupAt(unnamed, muscles, {"Loads", "passive", "muscle group"}, false), -1);
  EXPECT_EQ(test::deckErrorOf([&] { muscleGroupAt(unnamed, muscles, {"Loads", "passive", "muscle group"}, true); }),
            "deck built: parameter 'Loads/passive/muscle group': no muscle group '' in Material/Muscle groups (GGa, "
            "GGp)");
}

} // namespace
} // namespace glossa::input
