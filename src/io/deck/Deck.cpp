#include "io/deck/Deck.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <Teuchos_XMLParameterListCoreHelpers.hpp>
#include <Teuchos_XMLParameterListWriter.hpp>

#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "io/deck/SpecValidator.hpp"

namespace glossa::io {

namespace {
std::string knownNames(const Teuchos::ParameterList &valid) {
  std::string out;
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string &name = valid.name(it);
    if (name == kAnySublist) continue;
    out += (out.empty() ? "" : ", ") + name;
  }
  if (valid.isSublist(kAnySublist)) out += std::string(out.empty() ? "" : ", ") + "<any name> (a sublist)";
  return out.empty() ? "(none)" : out;
}

const SpecValidator *specOf(const Teuchos::ParameterEntry &entry) {
  return dynamic_cast<const SpecValidator *>(entry.validator().get());
}
} // namespace

std::string joinPath(const std::vector<std::string> &path) {
  std::string out;
  for (const auto &p : path) out += (out.empty() ? "" : "/") + p;
  return out;
}

Deck Deck::fromFile(const std::string &path) {
  Deck deck;
  deck.file_ = path;
  deck.list_.setName("Glossa");
  std::ifstream in(path);
  if (!in) throw DeckError("deck " + path + ": cannot be opened (does the file exist?)");
  std::stringstream text;
  text << in.rdbuf();
  std::string line;
  std::istringstream lines(text.str());
  while (std::getline(lines, line)) deck.lines_.push_back(line);
  try {
    Teuchos::updateParametersFromXmlString(text.str(), Teuchos::ptrFromRef(deck.list_));
  } catch (const std::exception &e) {
    // Teuchos prefixes its reason with source locations; the last line is the reason.
    std::string reason = e.what();
    while (!reason.empty() && reason.back() == '\n') reason.pop_back();
    reason = reason.substr(reason.find_last_of('\n') + 1);
    throw DeckError("deck " + path + ": not a valid Teuchos ParameterList XML file: " + reason);
  }
  return deck;
}

Deck Deck::fromList(const Teuchos::ParameterList &list, const std::string &label) {
  Deck deck;
  deck.file_ = label;
  deck.list_ = list;
  return deck;
}

int Deck::lineOf(const std::vector<std::string> &path) const {
  std::size_t line = 0;
  for (const auto &name : path) {
    const std::string needle = "name=\"" + name + "\"";
    while (line < lines_.size() && lines_[line].find(needle) == std::string::npos) ++line;
    if (line == lines_.size()) return 0;
  }
  return static_cast<int>(line) + 1;
}

std::string Deck::where(const std::vector<std::string> &path) const {
  const std::string joined = joinPath(path);
  std::string location = "deck " + file_;
  if (std::find(overridden_.begin(), overridden_.end(), joined) != overridden_.end())
    location += " (--set on the command line)";
  else if (const int line = lineOf(path); line > 0)
    location += ":" + std::to_string(line);
  return location + ": parameter '" + joined + "'";
}

void Deck::applyOverride(const std::string &assignment, const Teuchos::ParameterList &schema) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw DeckError("--set " + assignment + ": expected path/to/parameter=value");
  const std::string pathText = assignment.substr(0, eq);
  const std::string valueText = assignment.substr(eq + 1);
  std::vector<std::string> path;
  std::stringstream s(pathText);
  for (std::string part; std::getline(s, part, '/');) path.push_back(part);

  const Teuchos::ParameterList *valid = &schema;
  Teuchos::ParameterList *user = &list_;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    if (valid->isSublist(path[i])) valid = &valid->sublist(path[i]);
    else if (valid->isSublist(kAnySublist)) // a repeated section: --set may add one
      valid = &valid->sublist(kAnySublist);
    else
      throw DeckError("--set " + assignment + ": no section '" + path[i] + "' there; known: " +
                      knownNames(*valid));
    user = &user->sublist(path[i]);
  }
  const std::string &name = path.back();
  const Teuchos::ParameterEntry *declared = valid->getEntryPtr(name);
  if (declared == nullptr || declared->isList())
    throw DeckError("--set " + assignment + ": no parameter '" + name + "' there; known: " +
                    knownNames(*valid));
  const SpecValidator *spec = specOf(*declared);
  try {
    Teuchos::ParameterEntry entry = spec ? spec->parse(valueText) : Teuchos::ParameterEntry(valueText);
    user->setEntry(name, entry);
  } catch (const std::exception &e) {
    throw DeckError("--set " + assignment + ": " + e.what() + "; allowed: " +
                    (spec ? spec->allowed() : std::string("text")));
  }
  overridden_.push_back(joinPath(path));
}

void Deck::check(Teuchos::ParameterList &user, const Teuchos::ParameterList &valid,
                 std::vector<std::string> &path) const {
  for (auto it = user.begin(); it != user.end(); ++it) {
    const std::string &name = user.name(it);
    Teuchos::ParameterEntry &entry = user.getEntry(name);
    path.push_back(name);
    const Teuchos::ParameterEntry *declared = valid.getEntryPtr(name);
    if (declared == nullptr && entry.isList() && valid.isSublist(kAnySublist))
      declared = valid.getEntryPtr(kAnySublist);
    if (declared == nullptr)
      throw DeckError(where(path) + " is unknown; known here: " + knownNames(valid));
    if (declared->isList() != entry.isList())
      throw DeckError(where(path) + (declared->isList() ? " must be a ParameterList (a section)"
                                                         : " must be a Parameter, not a section"));
    if (entry.isList()) {
      check(Teuchos::getValue<Teuchos::ParameterList>(entry),
            Teuchos::getValue<Teuchos::ParameterList>(*declared), path);
    } else if (const SpecValidator *spec = specOf(*declared)) {
      const std::string why = spec->check(entry);
      if (!why.empty())
        throw DeckError(where(path) + " " + why + "; allowed: " + spec->allowed());
      // Keep the declared documentation with the user's value (for `glossa validate`).
      entry.setValidator(declared->validator());
      entry.setDocString(declared->docString());
    }
    path.pop_back();
  }
}

void Deck::fillDefaults(Teuchos::ParameterList &user, const Teuchos::ParameterList &valid) {
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string &name = valid.name(it);
    const Teuchos::ParameterEntry &declared = valid.entry(it);
    if (name == kAnySublist) {
      // Every user sublist not declared by name follows the template.
      for (auto u = user.begin(); u != user.end(); ++u)
        if (user.entry(u).isList() && !valid.isParameter(user.name(u)))
          fillDefaults(user.sublist(user.name(u)),
                       Teuchos::getValue<Teuchos::ParameterList>(declared));
      continue;
    }
    if (declared.isList())
      fillDefaults(user.sublist(name), Teuchos::getValue<Teuchos::ParameterList>(declared));
    else if (!user.isParameter(name))
      user.setEntry(name, declared);
  }
}

void Deck::validate(const Teuchos::ParameterList &schema) {
  std::vector<std::string> path;
  check(list_, schema, path);
  fillDefaults(list_, schema);
}

namespace {
// Teuchos' XML writer knows only its own validators: write plain entries whose doc string
// carries the declared description and allowed values instead.
Teuchos::ParameterList documentedCopy(const Teuchos::ParameterList &list) {
  Teuchos::ParameterList out(list.name());
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string &name = list.name(it);
    const Teuchos::ParameterEntry &entry = list.entry(it);
    if (entry.isList()) {
      out.set(name, documentedCopy(Teuchos::getValue<Teuchos::ParameterList>(entry)));
      continue;
    }
    Teuchos::ParameterEntry plain(entry.getAny(false), false, false, entry.docString());
    if (const SpecValidator *spec = specOf(entry))
      plain.setDocString(entry.docString() + " (allowed: " + spec->allowed() + ")");
    out.setEntry(name, plain);
  }
  return out;
}
} // namespace

std::string Deck::toXml() const {
  std::ostringstream out;
  Teuchos::writeParameterListToXmlOStream(documentedCopy(list_), out);
  return out.str();
}

} // namespace glossa::io
