#pragma once
// The XML of a deck, read into elements that keep their line numbers. Glossa reads the XML
// itself rather than through Teuchos' reader so that every value reaches validation as the text
// the user wrote (io/deck/StrictNumber.hpp parses it), every message has a line, and a
// pathological file is refused before anything recursive sees it (Teuchos' reader segfaults on
// ParameterLists nested 10,000 deep). It reads the XML a Teuchos ParameterList is written in:
// elements with attributes, comments, an optional <?xml ...?> declaration and the five named
// and the numeric character references; DOCTYPE, CDATA and text between elements are refused.

#include <string>
#include <utility>
#include <vector>

namespace glossa::io {

struct DeckXmlElement {
  std::string tag;
  std::vector<std::pair<std::string, std::string>> attributes; // in the order written, decoded
  int line = 0;                                                 // where the start tag begins
  std::vector<DeckXmlElement> children;

  // The attribute's value, or nullptr if it is not given.
  const std::string *attribute(const std::string &name) const;
};

// Elements nested deeper than this are refused (a deck needs fewer than ten).
inline constexpr int kMaxDeckXmlDepth = 64;

// Parses `text` (the contents of `file`, named in errors) into its root element; throws
// DeckError "deck FILE:LINE: not valid XML: why" on the first problem.
DeckXmlElement parseDeckXml(const std::string &text, const std::string &file);

} // namespace glossa::io
