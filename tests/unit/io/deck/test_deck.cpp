// Deck validation: every kind of bad deck stops with a message naming the file, the line, the
// parameter path and what is allowed; good decks get every default.
#include <fstream>

#include <gtest/gtest.h>

#include "io/deck/Deck.hpp"
#include "ProcessScratch.hpp"
#include "io/deck/DeckError.hpp"
#include "io/deck/DeckReference.hpp"
#include "io/deck/ParameterSpec.hpp"

using glossa::io::Deck;
using glossa::io::DeckError;

namespace {

Teuchos::ParameterList schema() {
  using namespace glossa::io;
  Teuchos::ParameterList s("Glossa");
  auto &mat = s.sublist("Material");
  declareDouble(mat, "Poisson's ratio", 0.3, "", "nu", Range::open(-1.0, 0.5));
  declareDouble(mat, "shear modulus", 1e3, "Pa", "mu", Range::positive());
  declareString(mat, "element", "Q1P0", "formulation", {"Q1P0", "Q1"});
  auto &box = s.sublist("Box");
  declareIntArray(box, "cells", Teuchos::Array<int>(3, 4), "cells", 3, Range::closed(1, 100));
  Teuchos::ParameterList bc;
  declareString(bc, "node set", "", "set");
  declareDoubleArray(bc, "value", Teuchos::Array<double>(3, 0.0), "m", "value", 3);
  s.sublist("Boundary conditions").set(kAnySublist, bc);
  return s;
}

std::string writeDeck(const std::string &name, const std::string &body) {
  const std::string path = (glossa::test::processScratch() / name).string();
  std::ofstream(path) << "<ParameterList name=\"Glossa\">\n" << body << "</ParameterList>\n";
  return path;
}

std::string errorOf(Deck deck) {
  try {
    deck.validate(schema());
  } catch (const DeckError &e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST(Deck, FillsDefaultsIncludingRepeatedSections) {
  auto deck = Deck::fromFile(writeDeck("good.xml", R"X(
  <ParameterList name="Material">
    <Parameter name="Poisson's ratio" type="double" value="0.45"/>
  </ParameterList>
  <ParameterList name="Boundary conditions">
    <ParameterList name="left"><Parameter name="node set" type="string" value="xmin"/></ParameterList>
  </ParameterList>
)X"));
  deck.validate(schema());
  EXPECT_EQ(deck.root().sublist("Material").get<double>("Poisson's ratio"), 0.45);
  EXPECT_EQ(deck.root().sublist("Material").get<double>("shear modulus"), 1e3);
  EXPECT_EQ(deck.root().sublist("Box").get<Teuchos::Array<int>>("cells").size(), 3);
  EXPECT_EQ(deck.root().sublist("Boundary conditions").sublist("left").get<Teuchos::Array<double>>("value").size(), 3);
  EXPECT_NE(deck.toXml().find("allowed: real number, -1 &lt; value &lt; 0.5"), std::string::npos);
}

TEST(Deck, UnknownKeyNamesFileLinePathAndKnownKeys) {
  const auto path = writeDeck("unknown.xml", R"X(
  <ParameterList name="Material">
    <Parameter name="poisson ratio" type="double" value="0.45"/>
  </ParameterList>
)X");
  const std::string msg = errorOf(Deck::fromFile(path));
  EXPECT_NE(msg.find(path + ":4"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'Material/poisson ratio' is unknown"), std::string::npos) << msg;
  EXPECT_NE(msg.find("Poisson's ratio"), std::string::npos) << msg;
}

TEST(Deck, WrongTypeIsRefused) {
  const std::string msg = errorOf(Deck::fromFile(writeDeck("type.xml", R"X(
  <ParameterList name="Material">
    <Parameter name="shear modulus" type="string" value="soft"/>
  </ParameterList>
)X")));
  EXPECT_NE(msg.find("'Material/shear modulus' has type"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must be double"), std::string::npos) << msg;
}

TEST(Deck, OutOfRangeValueNamesTheAllowedRange) {
  for (const char *nu : {"0.5", "0.6", "-1"}) {
    const std::string msg = errorOf(Deck::fromFile(writeDeck("range.xml", std::string(R"X(
  <ParameterList name="Material">
    <Parameter name="Poisson's ratio" type="double" value=")X") + nu + R"X("/>
  </ParameterList>
)X")));
    EXPECT_NE(msg.find("out of range"), std::string::npos) << msg;
    EXPECT_NE(msg.find("-1 < value < 0.5"), std::string::npos) << msg;
  }
}

TEST(Deck, WordNotInTheAllowedListAndWrongArraySize) {
  std::string msg = errorOf(Deck::fromFile(writeDeck("word.xml", R"X(
  <ParameterList name="Material"><Parameter name="element" type="string" value="Q2"/></ParameterList>
)X")));
  EXPECT_NE(msg.find("one of: Q1P0, Q1"), std::string::npos) << msg;
  msg = errorOf(Deck::fromFile(writeDeck("array.xml", R"X(
  <ParameterList name="Box"><Parameter name="cells" type="Array(int)" value="{4, 4}"/></ParameterList>
)X")));
  EXPECT_NE(msg.find("has 2 entries"), std::string::npos) << msg;
}

TEST(Deck, MalformedXmlAndMissingFileAreDeckErrors) {
  const auto path = writeDeck("broken.xml", "<ParameterList name=\"Material\">\n");
  EXPECT_THROW(Deck::fromFile(path), DeckError);
  EXPECT_THROW(Deck::fromFile("/nonexistent/deck.xml"), DeckError);
}

TEST(Deck, CommandLineOverridesAreTypedAndChecked) {
  auto deck = Deck::fromFile(writeDeck("override.xml", ""));
  deck.applyOverride("Box/cells=16,16,16", schema());
  deck.applyOverride("Material/Poisson's ratio=0.49", schema());
  deck.validate(schema());
  EXPECT_EQ(deck.root().sublist("Box").get<Teuchos::Array<int>>("cells")[2], 16);
  EXPECT_EQ(deck.root().sublist("Material").get<double>("Poisson's ratio"), 0.49);
  EXPECT_THROW(deck.applyOverride("Box/cellz=4", schema()), DeckError);
  EXPECT_THROW(deck.applyOverride("Material/shear modulus=abc", schema()), DeckError);
  auto bad = Deck::fromFile(writeDeck("override2.xml", ""));
  bad.applyOverride("Material/Poisson's ratio=0.5", schema());
  const std::string msg = errorOf(bad);
  EXPECT_NE(msg.find("--set on the command line"), std::string::npos) << msg;
}

TEST(Deck, ValuesAreReadStrictlyWithFileLinePathTextAndWhatIsAllowed) {
  // Each of these was read as a different number without a word before (strtod).
  for (const char *nu : {"0,4999", "3.5abc", "2 3", "0x10", "", "eighty", "{}", "1e999", "inf", "nan"}) {
    const auto path = writeDeck("strict.xml", std::string(R"X(  <ParameterList name="Material">
    <Parameter name="Poisson's ratio" type="double" value=")X") + nu + R"X("/>
  </ParameterList>
)X");
    const std::string msg = errorOf(Deck::fromFile(path));
    EXPECT_NE(msg.find(path + ":3: parameter 'Material/Poisson's ratio': "), std::string::npos) << msg;
    if (*nu) EXPECT_NE(msg.find(std::string("'") + nu + "'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("allowed: real number, -1 < value < 0.5"), std::string::npos) << msg;
  }
  // One bad entry refuses the array instead of zeroing it.
  for (const char *value : {"{0, abc, 0}", "{nan,0,0}", "{0,-inf,0}", "{-1,-1, }"}) {
    const std::string msg = errorOf(Deck::fromFile(writeDeck("array.xml", std::string(R"X(  <ParameterList name="Boundary conditions">
    <ParameterList name="left"><Parameter name="value" type="Array(double)" value=")X") + value + R"X("/></ParameterList>
  </ParameterList>
)X")));
    EXPECT_NE(msg.find("'Boundary conditions/left/value': "), std::string::npos) << msg;
    EXPECT_NE(msg.find("entry"), std::string::npos) << msg;
  }
  for (const char *cells : {"{4.5,4,4}", "{1e308,2,2}"})
    EXPECT_NE(errorOf(Deck::fromFile(writeDeck("cells.xml", std::string(R"X(  <ParameterList name="Box">
    <Parameter name="cells" type="Array(int)" value=")X") + cells + R"X("/>
  </ParameterList>
)X"))).find("is not an integer"),
              std::string::npos)
        << cells;
}

TEST(Deck, OutOfRangeValuesAreShownAsWritten) {
  // 0.49999999999999999 is 0.5 as a double; 0.4999999999999999 is not, and shows all its digits.
  std::string msg = errorOf(Deck::fromFile(writeDeck("range2.xml", R"X(  <ParameterList name="Material">
    <Parameter name="Poisson's ratio" type="double" value="0.50000000000001"/>
  </ParameterList>
)X")));
  EXPECT_NE(msg.find("= 0.50000000000001 is out of range"), std::string::npos) << msg;
  msg = errorOf(Deck::fromFile(writeDeck("range3.xml", R"X(  <ParameterList name="Box">
    <Parameter name="cells" type="Array(int)" value="{4, 0, 4}"/>
  </ParameterList>
)X")));
  EXPECT_NE(msg.find("has entry 2 = 0 out of range"), std::string::npos) << msg;
}

TEST(Deck, ParameterGivenTwiceIsRefusedWithBothLines) {
  try {
    Deck::fromFile(writeDeck("twice.xml", R"X(  <ParameterList name="Material">
    <Parameter name="shear modulus" type="double" value="1000"/>
    <Parameter name="shear modulus" type="double" value="2000"/>
  </ParameterList>
)X"));
    ADD_FAILURE() << "accepted";
  } catch (const DeckError &e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("twice.xml:4: 'Material/shear modulus' is given twice (first on line 3)"), std::string::npos) << msg;
  }
  // A section given twice as well (Teuchos merged the two).
  EXPECT_THROW(Deck::fromFile(writeDeck("twice2.xml", R"X(  <ParameterList name="Material"/>
  <ParameterList name="Material"/>
)X")),
               DeckError);
}

TEST(Deck, RefusesElementsTypesAndAttributesADeckDoesNotHave) {
  const std::pair<const char *, const char *> cases[] = {
      {R"(<Parameter name="x" type="float" value="1"/>)", "has type \"float\"; a deck's types are"},
      {R"(<Parameter name="x" type="double"/>)", "needs both type"},
      {R"(<Parameter type="double" value="1"/>)", "needs a name"},
      {R"(<Parameter name="x" type="double" value="1" unit="Pa"/>)", "has no attribute 'unit'"},
      {R"(<Param name="x"/>)", "<Param> is not part of a deck"},
  };
  for (const auto &[body, expected] : cases) {
    try {
      Deck::fromFile(writeDeck("elements.xml", std::string("  ") + body + "\n"));
      ADD_FAILURE() << body;
    } catch (const DeckError &e) {
      EXPECT_NE(std::string(e.what()).find(std::string("elements.xml:2: ")), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
}

TEST(Deck, WrittenDeckReadsBack) {
  auto deck = Deck::fromFile(writeDeck("written.xml", R"X(  <ParameterList name="Material">
    <Parameter name="Poisson's ratio" type="double" value="0.45"/>
  </ParameterList>
)X"));
  deck.validate(schema());
  const std::string path = (glossa::test::processScratch() / "written_back.xml").string();
  std::ofstream(path) << deck.toXml();
  auto again = Deck::fromFile(path);
  again.validate(schema());
  EXPECT_EQ(again.root().sublist("Material").get<double>("Poisson's ratio"), 0.45);
  EXPECT_EQ(again.root().sublist("Box").get<Teuchos::Array<int>>("cells"), Teuchos::Array<int>(3, 4));
}

TEST(Deck, CommandLineValuesAreAsStrictAsTheFile) {
  auto deck = Deck::fromFile(writeDeck("override3.xml", ""));
  for (const char *assignment : {"Material/shear modulus=1e999", "Material/shear modulus=inf", "Material/shear modulus=3.5abc",
                                 "Box/cells=4,,4", "Box/cells=4 4,4"}) {
    try {
      deck.applyOverride(assignment, schema());
      ADD_FAILURE() << assignment;
    } catch (const DeckError &e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.find("stod"), std::string::npos) << msg;
      EXPECT_NE(msg.find("allowed: "), std::string::npos) << msg;
    }
  }
  // A bad value in the file is replaced by a good one on the command line.
  auto fixed = Deck::fromFile(writeDeck("override4.xml", R"X(  <ParameterList name="Material">
    <Parameter name="Poisson's ratio" type="double" value="0,45"/>
  </ParameterList>
)X"));
  fixed.applyOverride("Material/Poisson's ratio=0.45", schema());
  fixed.validate(schema());
  EXPECT_EQ(fixed.root().sublist("Material").get<double>("Poisson's ratio"), 0.45);
}

// A number whose text is not the bound of its range but whose double is: 0.49999999999999999999
// becomes 0.5, which Poisson's ratio allows as exact incompressibility, though the author wrote a
// number below it. Refused, in the file as with --set; the bound written as itself is not.
TEST(Deck, ATextReadAsTheBoundItIsNotIsRefused) {
  Teuchos::ParameterList closed("Glossa");
  glossa::io::declareDouble(closed.sublist("Material"), "Poisson's ratio", 0.3, "", "nu", {-1.0, 0.5, true, false});
  auto withNu = [&](const std::string &name, const std::string &text) {
    auto deck = Deck::fromFile(writeDeck(name, "  <ParameterList name=\"Material\">\n    <Parameter name=\"Poisson's "
                                                 "ratio\" type=\"double\" value=\"" + text + "\"/>\n  </ParameterList>\n"));
    deck.validate(closed);
    return deck.root().sublist("Material").get<double>("Poisson's ratio");
  };
  try {
    withNu("bound1.xml", "0.49999999999999999999");
    ADD_FAILURE() << "accepted";
  } catch (const DeckError &e) {
    EXPECT_NE(std::string(e.what()).find("bound1.xml:3: parameter 'Material/Poisson's ratio' = '0.49999999999999999999' is "
                                         "read as 0.5 (the nearest double), the bound of its range, which the text is "
                                         "not; write 0.5 if that is meant, or a value a double tells apart from it (the "
                                         "nearest inside: 0.49999999999999994)"),
              std::string::npos)
        << e.what();
  }
  for (const char *half : {"0.5", "0.50", "+.5", "5e-1", " 0.5 "}) EXPECT_EQ(withNu("bound2.xml", half), 0.5) << half;
  EXPECT_LT(withNu("bound3.xml", "0.4999999999999999"), 0.5);
  auto deck = Deck::fromFile(writeDeck("bound4.xml", ""));
  deck.applyOverride("Material/Poisson's ratio=0.500000000000000000001", closed);
  try {
    deck.validate(closed);
    ADD_FAILURE() << "accepted";
  } catch (const DeckError &e) {
    EXPECT_NE(std::string(e.what()).find("(--set on the command line): parameter 'Material/Poisson's ratio' = "
                                         "'0.500000000000000000001' is read as 0.5"),
              std::string::npos)
        << e.what();
  }
}

// --set keeps what the file gave (Time/end time for the ramps, Material's nu beside a bulk
// modulus); nothing for a parameter the file did not give or --set did not touch.
TEST(Deck, TheFilesValueReplacedByTheCommandLineIsKept) {
  auto deck = Deck::fromFile(writeDeck("file_value.xml", R"X(  <ParameterList name="Material">
    <Parameter name="shear modulus" type="double" value="2000"/>
    <Parameter name="Poisson's ratio" type="double" value="0.25"/>
  </ParameterList>
)X"));
  deck.applyOverride("Material/shear modulus=3000", schema());
  deck.applyOverride("Material/shear modulus=4000", schema());
  deck.applyOverride("Material/element=Q1", schema());
  deck.validate(schema());
  EXPECT_EQ(deck.root().sublist("Material").get<double>("shear modulus"), 4000.0);
  ASSERT_NE(deck.fileValue({"Material", "shear modulus"}), nullptr);
  EXPECT_EQ(Teuchos::getValue<double>(*deck.fileValue({"Material", "shear modulus"})), 2000.0);
  EXPECT_TRUE(deck.setOnCommandLine({"Material", "shear modulus"}));
  EXPECT_EQ(deck.fileValue({"Material", "Poisson's ratio"}), nullptr);
  EXPECT_FALSE(deck.setOnCommandLine({"Material", "Poisson's ratio"}));
  EXPECT_EQ(deck.fileValue({"Material", "element"}), nullptr); // --set, but not in the file
  EXPECT_TRUE(deck.setOnCommandLine({"Material", "element"}));
}

TEST(DeckReference, ListsEveryDeclaredParameterWithItsRange) {
  std::ostringstream out;
  glossa::io::writeDeckReference(schema(), out);
  const std::string text = out.str();
  for (const char *needle : {"`Material`", "`Poisson's ratio`", "-1 < value < 0.5", "`Boundary conditions/<any name>`",
                             "one of: Q1P0, Q1"})
    EXPECT_NE(text.find(needle), std::string::npos) << needle;
}
