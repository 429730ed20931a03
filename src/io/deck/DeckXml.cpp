#include "io/deck/DeckXml.hpp"

#include <cstdint>

#include "io/deck/DeckError.hpp"

namespace glossa::io {

const std::string *DeckXmlElement::attribute(const std::string &name) const {
  for (const auto &[key, value] : attributes)
    if (key == name) return &value;
  return nullptr;
}

namespace {

class Reader {
public:
  Reader(const std::string &text, const std::string &file) : s_(text), file_(file) {
    if (s_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3; // a UTF-8 byte-order mark
  }

  DeckXmlElement document() {
    skipMisc(true);
    if (atEnd()) fail("the file holds no element (a deck is one <ParameterList name=\"Glossa\">)");
    if (!startsWith("<") || startsWith("</")) fail("expected an element here");
    DeckXmlElement root = element(1);
    skipMisc(false);
    if (!atEnd()) fail("text after the end of the root element '" + root.tag + "'");
    return root;
  }

private:
  [[noreturn]] void fail(const std::string &why) const { failAt(line_, why); }
  [[noreturn]] void failAt(int line, const std::string &why) const {
    throw DeckError("deck " + file_ + ":" + std::to_string(line) + ": not valid XML: " + why);
  }

  bool atEnd() const { return pos_ >= s_.size(); }
  bool startsWith(const char *prefix) const { return s_.compare(pos_, std::char_traits<char>::length(prefix), prefix) == 0; }
  char peek() const { return atEnd() ? '\0' : s_[pos_]; }
  void advance(std::size_t n = 1) {
    for (std::size_t i = 0; i < n && !atEnd(); ++i, ++pos_)
      if (s_[pos_] == '\n') ++line_;
  }
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
  void skipSpace() {
    while (!atEnd() && isSpace(peek())) advance();
  }
  static bool isNameChar(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-' || c == '.' || c == ':' || static_cast<unsigned char>(c) >= 0x80;
  }

  void skipUntil(const char *terminator, const std::string &what) {
    const int start = line_;
    const auto end = s_.find(terminator, pos_);
    if (end == std::string::npos) failAt(start, what + " is never closed");
    advance(end + std::char_traits<char>::length(terminator) - pos_);
  }

  // Blanks, comments and (before the root only) the XML declaration.
  void skipMisc(bool beforeRoot) {
    while (true) {
      skipSpace();
      if (startsWith("<!--")) skipUntil("-->", "a comment <!--");
      else if (beforeRoot && startsWith("<?xml")) skipUntil("?>", "the declaration <?xml");
      else if (startsWith("<!DOCTYPE") || startsWith("<!ENTITY")) fail("a DOCTYPE or ENTITY declaration is not read in a deck");
      else if (startsWith("<![CDATA[")) fail("CDATA sections are not read in a deck; give values as attributes");
      else if (startsWith("<?")) fail("a processing instruction <? is not read in a deck");
      else return;
    }
  }

  std::string name(const char *what) {
    const std::size_t start = pos_;
    while (!atEnd() && isNameChar(peek())) advance();
    if (pos_ == start) fail(std::string("expected ") + what + " name");
    return s_.substr(start, pos_ - start);
  }

  static void appendUtf8(std::string &out, std::uint32_t c) {
    if (c < 0x80) out += static_cast<char>(c);
    else if (c < 0x800) {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      out += static_cast<char>(0xE0 | (c >> 12));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (c >> 18));
      out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }

  // The text of a character reference after '&', up to and including ';'.
  void reference(std::string &out) {
    const auto semicolon = s_.find(';', pos_);
    if (semicolon == std::string::npos || semicolon - pos_ > 12)
      fail("a '&' that starts no reference (write &amp; for a literal &)");
    const std::string ref = s_.substr(pos_ + 1, semicolon - pos_ - 1);
    if (ref == "lt") out += '<';
    else if (ref == "gt") out += '>';
    else if (ref == "amp") out += '&';
    else if (ref == "quot") out += '"';
    else if (ref == "apos") out += '\'';
    else if (ref.size() > 1 && ref[0] == '#') {
      const bool hex = ref[1] == 'x' || ref[1] == 'X';
      const std::string digits = ref.substr(hex ? 2 : 1);
      std::uint32_t code = 0;
      if (digits.empty()) fail("an empty character reference &" + ref + ";");
      for (char c : digits) {
        int d = -1;
        if (c >= '0' && c <= '9') d = c - '0';
        else if (hex && c >= 'a' && c <= 'f') d = c - 'a' + 10;
        else if (hex && c >= 'A' && c <= 'F') d = c - 'A' + 10;
        if (d < 0 || code > 0x10FFFF) fail("a bad character reference &" + ref + ";");
        code = code * (hex ? 16 : 10) + static_cast<std::uint32_t>(d);
      }
      if (code == 0 || code > 0x10FFFF) fail("a character reference &" + ref + "; out of range");
      appendUtf8(out, code);
    } else
      fail("an unknown entity &" + ref + "; (known: &lt; &gt; &amp; &quot; &apos; and &#N;)");
    advance(semicolon + 1 - pos_);
  }

  std::string attributeValue() {
    const char quote = peek();
    if (quote != '"' && quote != '\'') fail("an attribute value must be in quotes");
    const int start = line_;
    advance();
    std::string value;
    while (true) {
      if (atEnd()) failAt(start, "an attribute value is never closed");
      const char c = peek();
      if (c == quote) break;
      if (c == '<') fail("a '<' inside an attribute value (write &lt;)");
      if (c == '&') {
        reference(value);
        continue;
      }
      value += c;
      advance();
    }
    advance();
    return value;
  }

  DeckXmlElement element(int depth) {
    if (depth > kMaxDeckXmlDepth)
      fail("elements nested more than " + std::to_string(kMaxDeckXmlDepth) + " deep");
    DeckXmlElement e;
    e.line = line_;
    advance(); // '<'
    e.tag = name("an element");
    while (true) {
      const bool spaced = isSpace(peek());
      skipSpace();
      if (startsWith("/>")) {
        advance(2);
        return e;
      }
      if (peek() == '>') {
        advance();
        break;
      }
      if (atEnd()) failAt(e.line, "the tag <" + e.tag + " is never closed");
      if (!spaced) fail("expected a blank between attributes of <" + e.tag + ">");
      const std::string key = name("an attribute");
      if (e.attribute(key)) fail("attribute '" + key + "' is given twice in <" + e.tag + ">");
      skipSpace();
      if (peek() != '=') fail("expected '=' after attribute '" + key + "'");
      advance();
      skipSpace();
      e.attributes.emplace_back(key, attributeValue());
    }
    while (true) {
      skipMisc(false);
      if (atEnd()) failAt(e.line, "<" + e.tag + "> is never closed (no </" + e.tag + ">)");
      if (startsWith("</")) {
        advance(2);
        const std::string closing = name("a closing element");
        skipSpace();
        if (peek() != '>') fail("expected '>' to end </" + closing);
        if (closing != e.tag)
          fail("</" + closing + "> closes <" + e.tag + "> opened on line " + std::to_string(e.line));
        advance();
        return e;
      }
      if (peek() == '<') e.children.push_back(element(depth + 1));
      else fail("text between elements (inside <" + e.tag + ">); a deck gives values as attributes");
    }
  }

  const std::string &s_;
  const std::string &file_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

} // namespace

DeckXmlElement parseDeckXml(const std::string &text, const std::string &file) {
  return Reader(text, file).document();
}

} // namespace glossa::io
