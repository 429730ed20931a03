#pragma once
// An input deck: a Teuchos XML ParameterList read from a file, checked against the schema that
// the objects of Glossa declare (io/deck/ParameterSpec.hpp) and completed with their defaults.
// Validation happens before anything runs; every error names file, line, parameter path and
// what is allowed (DeckError).

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

namespace glossa::io {

class Deck {
public:
  // Reads and parses the XML file; throws DeckError if the file is missing or not valid XML.
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

  // The deck (after validation: fully defaulted) as Teuchos XML.
  std::string toXml() const;

private:
  void check(Teuchos::ParameterList &user, const Teuchos::ParameterList &valid,
             std::vector<std::string> &path) const;
  static void fillDefaults(Teuchos::ParameterList &user, const Teuchos::ParameterList &valid);
  int lineOf(const std::vector<std::string> &path) const;

  std::string file_;
  std::vector<std::string> lines_;
  std::vector<std::string> overridden_; // paths set on the command line
  Teuchos::ParameterList list_;
};

std::string joinPath(const std::vector<std::string> &path);

} // namespace glossa::io
