#pragma once
// An input deck: a Teuchos XML ParameterList read from a file, checked against the schema that
// the objects of Glossa declare (io/deck/ParameterSpec.hpp) and completed with their defaults.
// Validation happens before anything runs; every error names file, line, parameter path and
// what is allowed (DeckError).

#include <map>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

namespace glossa::io {

struct DeckXmlElement;

class Deck {
public:
  // Reads and parses the XML file (io/deck/DeckXml.hpp); throws DeckError if the file is
  // missing, is not valid XML, holds an element or type a deck does not have, or gives a
  // parameter twice. A value that is not exactly one value of its type ("0,4999", "3.5abc",
  // "{0, abc, 0}") is kept aside and refused by validate(), which knows what is allowed.
  static Deck fromFile(const std::string &path);
  // A deck built in code (tests, benchmarks); `label` stands for the file name in errors.
  static Deck fromList(const Teuchos::ParameterList &list, const std::string &label);

  // Applies "path/to/parameter=value" (from --set) before validation; the value is parsed with
  // the type the schema declares for that path. Throws DeckError for an unknown path or value.
  void applyOverride(const std::string &assignment, const Teuchos::ParameterList &schema);

  // Checks every entry against `schema` (unknown names, types, ranges, allowed words) and fills
  // in every default. Throws DeckError naming the first problem.
  void validate(const Teuchos::ParameterList &schema);

  Teuchos::ParameterList &root() { return list_; }
  const Teuchos::ParameterList &root() const { return list_; }
  const std::string &file() const { return file_; }

  // "FILE:LINE: parameter 'A/B/c'" for messages of later checks (e.g. a missing mesh set).
  std::string where(const std::vector<std::string> &path) const;
  // Whether the user gave the parameter (in the file or by --set), not its default.
  bool given(const std::vector<std::string> &path) const;
  // Whether --set gave the parameter (over the file's value, if it had one).
  bool setOnCommandLine(const std::vector<std::string> &path) const;
  // The value the file gave for a parameter that --set then replaced; null if the file gave none
  // or --set did not replace it. Not validated: what it holds is as the file wrote it.
  const Teuchos::ParameterEntry *fileValue(const std::vector<std::string> &path) const;

  // The deck (after validation: fully defaulted) as Teuchos XML.
  std::string toXml() const;

private:
  // Builds `list` from the children of `element` (a <ParameterList>), recording lines and texts
  // that are not values.
  void read(const DeckXmlElement &element, Teuchos::ParameterList &list, std::vector<std::string> &path);
  void check(Teuchos::ParameterList &user, const Teuchos::ParameterList &valid,
             std::vector<std::string> &path) const;
  static void fillDefaults(Teuchos::ParameterList &user, const Teuchos::ParameterList &valid);
  int lineOf(const std::vector<std::string> &path) const;

  std::string file_;
  std::map<std::string, int> lines_;          // joined path -> line of its element in the file
  std::map<std::string, std::string> invalid_; // joined path -> why its text is not a value
  std::map<std::string, std::string> doubleTexts_; // joined path -> a double's text, as written
  std::vector<std::string> overridden_; // paths set on the command line
  std::map<std::string, Teuchos::ParameterEntry> fileValues_; // joined path -> the file's value --set replaced
  Teuchos::ParameterList list_;
};

std::string joinPath(const std::vector<std::string> &path);

} // namespace glossa::io
