// The deck's XML reader: structure and line numbers of what it reads, and a clear refusal
// (file:line, why) of what is not deck XML, including a file nested deep enough to crash a
// recursive reader.
#include <gtest/gtest.h>

#include "io/deck/DeckError.hpp"
#include "io/deck/DeckXml.hpp"

using glossa::io::DeckError;
using glossa::io::DeckXmlElement;
using glossa::io::parseDeckXml;

namespace {
std::string errorOf(const std::string &text) {
  try {
    parseDeckXml(text, "d.xml");
  } catch (const DeckError &e) {
    return e.what();
  }
  return "";
}
} // namespace

TEST(DeckXml, ReadsElementsAttributesAndLines) {
  const DeckXmlElement root = parseDeckXml(
      "\xEF\xBB\xBF<?xml version=\"1.0\"?>\n<!-- a comment -->\n<ParameterList name=\"Glossa\">\n"
      "  <Parameter name='a &amp; b' type=\"string\" value=\"&lt;&#65;&#x42;&quot;&apos;&gt;\"/>\n"
      "  <!-- another\n comment -->\n"
      "  <ParameterList name=\"Time\"\n    >\n    <Parameter name=\"end time\" type=\"double\" value=\"1\"/>\n"
      "  </ParameterList>\n</ParameterList>\n",
      "d.xml");
  EXPECT_EQ(root.tag, "ParameterList");
  EXPECT_EQ(root.line, 3);
  ASSERT_EQ(root.children.size(), 2u);
  EXPECT_EQ(*root.children[0].attribute("name"), "a & b");
  EXPECT_EQ(*root.children[0].attribute("value"), "<AB\"'>");
  EXPECT_EQ(root.children[0].line, 4);
  EXPECT_EQ(root.children[1].line, 7);
  EXPECT_EQ(root.children[1].children[0].line, 9);
  EXPECT_EQ(root.children[1].attribute("type"), nullptr);
}

TEST(DeckXml, RefusesMalformedFilesWithTheirLine) {
  EXPECT_NE(errorOf("<ParameterList name=\"G\">\n<Parameter name=\"a\"/>\n").find("d.xml:1: not valid XML: <ParameterList> is never closed"),
            std::string::npos);
  EXPECT_NE(errorOf("<A>\n</B>").find("d.xml:2: not valid XML: </B> closes <A> opened on line 1"), std::string::npos);
  EXPECT_NE(errorOf("<A x=\"1\" x=\"2\"/>").find("attribute 'x' is given twice"), std::string::npos);
  EXPECT_NE(errorOf("<A x=1/>").find("in quotes"), std::string::npos);
  EXPECT_NE(errorOf("<A x=\"a<b\"/>").find("'<' inside an attribute"), std::string::npos);
  EXPECT_NE(errorOf("<A x=\"&nbsp;\"/>").find("unknown entity &nbsp;"), std::string::npos);
  EXPECT_NE(errorOf("<A x=\"&#0;\"/>").find("out of range"), std::string::npos);
  EXPECT_NE(errorOf("<A>text</A>").find("text between elements"), std::string::npos);
  EXPECT_NE(errorOf("<A/><B/>").find("text after the end of the root element"), std::string::npos);
  EXPECT_NE(errorOf("").find("holds no element"), std::string::npos);
  EXPECT_NE(errorOf("<!DOCTYPE x [<!ENTITY a \"b\">]><A/>").find("DOCTYPE"), std::string::npos);
  EXPECT_NE(errorOf("<A><![CDATA[x]]></A>").find("CDATA"), std::string::npos);
  EXPECT_NE(errorOf("<A><!-- open").find("d.xml:1: not valid XML: a comment <!-- is never closed"), std::string::npos);
  EXPECT_NE(errorOf("<A x=\"1\"y=\"2\"/>").find("blank between attributes"), std::string::npos);
}

TEST(DeckXml, RefusesDeepNestingBeforeAnythingRecursiveSeesIt) {
  // Teuchos' reader segfaults on this file (10,000 nested ParameterLists).
  std::string text;
  for (int i = 0; i < 10000; ++i) text += "<ParameterList name=\"n\">\n";
  for (int i = 0; i < 10000; ++i) text += "</ParameterList>\n";
  const std::string message = errorOf(text);
  EXPECT_NE(message.find("d.xml:65: not valid XML: elements nested more than 64 deep"), std::string::npos) << message;
  // The deepest allowed nesting reads.
  std::string fits;
  for (int i = 0; i < glossa::io::kMaxDeckXmlDepth; ++i) fits += "<L>";
  for (int i = 0; i < glossa::io::kMaxDeckXmlDepth; ++i) fits += "</L>";
  EXPECT_EQ(errorOf(fits), "");
}
