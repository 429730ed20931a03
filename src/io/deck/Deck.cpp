#include "io/deck/Deck.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <Teuchos_XMLParameterListCoreHelpers.hpp>

#include "io/deck/DeckError.hpp"
#include "io/deck/DeckXml.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "io/deck/SpecValidator.hpp"
#include "io/deck/StrictNumber.hpp"

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

namespace {
bool allowedAttribute(const std::string &tag, const std::string &key) {
  // Teuchos' writer adds id, docString, isDefault, isUsed and validatorId: a deck written by
  // Glossa or Teuchos reads back.
  static const std::vector<std::string> list{"name", "id"};
  static const std::vector<std::string> parameter{"name", "type", "value", "docString", "isDefault", "isUsed",
                                                  "id", "validatorId"};
  const auto &known = tag == "ParameterList" ? list : parameter;
  return std::find(known.begin(), known.end(), key) != known.end();
}

// A parameter's value from its text, by the type its XML declares; std::invalid_argument if the
// text is not exactly one value of that type.
Teuchos::ParameterEntry entryOf(const std::string &type, const std::string &text) {
  Teuchos::ParameterEntry entry;
  if (type == "double") entry.setValue(parseStrictDouble(text));
  else if (type == "int") entry.setValue(parseStrictInt(text));
  else if (type == "bool") entry.setValue(parseStrictBool(text));
  else if (type == "string") entry.setValue(text);
  else if (type == "Array(double)") {
    const auto v = parseStrictDoubleArray(text, true);
    entry.setValue(Teuchos::Array<double>(v.begin(), v.end()));
  } else if (type == "Array(int)") {
    const auto v = parseStrictIntArray(text, true);
    entry.setValue(Teuchos::Array<int>(v.begin(), v.end()));
  }
  return entry;
}
} // namespace

void Deck::read(const DeckXmlElement &element, Teuchos::ParameterList &list, std::vector<std::string> &path) {
  auto at = [&](const DeckXmlElement &e) { return "deck " + file_ + ":" + std::to_string(e.line) + ": "; };
  for (const DeckXmlElement &child : element.children) {
    if ((child.tag == "Validators" || child.tag == "Dependencies") && child.children.empty() &&
        child.attributes.empty())
      continue; // what Teuchos' writer adds when there are none
    if (child.tag != "ParameterList" && child.tag != "Parameter")
      throw DeckError(at(child) + "<" + child.tag + "> is not part of a deck (it holds <ParameterList name=...> and "
                      "<Parameter name=... type=... value=.../>)");
    for (const auto &[key, value] : child.attributes)
      if (!allowedAttribute(child.tag, key))
        throw DeckError(at(child) + "<" + child.tag + "> has no attribute '" + key + "'");
    const std::string *name = child.attribute("name");
    if (name == nullptr || name->empty())
      throw DeckError(at(child) + "<" + child.tag + "> needs a name=\"...\" attribute");
    path.push_back(*name);
    const std::string joined = joinPath(path);
    if (list.isParameter(*name))
      throw DeckError(at(child) + "'" + joined + "' is given twice (first on line " +
                      std::to_string(lines_[joined]) + "); give each parameter once");
    lines_[joined] = child.line;
    if (child.tag == "ParameterList") {
      read(child, list.sublist(*name), path);
    } else {
      if (!child.children.empty())
        throw DeckError(at(child) + "<Parameter name=\"" + *name + "\"> holds elements; a parameter is one empty element");
      const std::string *type = child.attribute("type");
      const std::string *value = child.attribute("value");
      if (type == nullptr || value == nullptr)
        throw DeckError(at(child) + "parameter '" + joined + "' needs both type=\"...\" and value=\"...\"");
      static const std::vector<std::string> types{"double", "int", "bool", "string", "Array(double)", "Array(int)"};
      if (std::find(types.begin(), types.end(), *type) == types.end())
        throw DeckError(at(child) + "parameter '" + joined + "' has type \"" + *type +
                        "\"; a deck's types are double, int, bool, string, Array(double) and Array(int)");
      if (*type == "double") doubleTexts_[joined] = *value;
      try {
        list.setEntry(*name, entryOf(*type, *value));
      } catch (const std::invalid_argument &e) {
        invalid_[joined] = e.what();
        list.set(*name, *value); // kept as text; validate() refuses it
      }
    }
    path.pop_back();
  }
}

Deck Deck::fromFile(const std::string &path) {
  Deck deck;
  deck.file_ = path;
  deck.list_.setName("Glossa");
  std::ifstream in(path);
  if (!in) throw DeckError("deck " + path + ": cannot be opened (does the file exist?)");
  std::stringstream text;
  text << in.rdbuf();
  const DeckXmlElement root = parseDeckXml(text.str(), path);
  if (root.tag != "ParameterList")
    throw DeckError("deck " + path + ":" + std::to_string(root.line) + ": the root element is <" + root.tag +
                    ">; a deck is one <ParameterList name=\"Glossa\">");
  std::vector<std::string> names;
  deck.read(root, deck.list_, names);
  return deck;
}

Deck Deck::fromList(const Teuchos::ParameterList &list, const std::string &label) {
  Deck deck;
  deck.file_ = label;
  deck.list_ = list;
  return deck;
}

int Deck::lineOf(const std::vector<std::string> &path) const {
  const auto it = lines_.find(joinPath(path));
  return it == lines_.end() ? 0 : it->second;
}

bool Deck::given(const std::vector<std::string> &path) const {
  const std::string joined = joinPath(path);
  return lineOf(path) > 0 || std::find(overridden_.begin(), overridden_.end(), joined) != overridden_.end();
}

bool Deck::setOnCommandLine(const std::vector<std::string> &path) const {
  return std::find(overridden_.begin(), overridden_.end(), joinPath(path)) != overridden_.end();
}

const Teuchos::ParameterEntry *Deck::fileValue(const std::vector<std::string> &path) const {
  const auto it = fileValues_.find(joinPath(path));
  return it == fileValues_.end() ? nullptr : &it->second;
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
    const std::string joined = joinPath(path);
    if (user->isParameter(name) && !user->getEntry(name).isList() && lineOf(path) > 0 && !fileValues_.count(joined))
      fileValues_[joined] = user->getEntry(name);
    user->setEntry(name, entry);
    invalid_.erase(joinPath(path));
    if (entry.getAny(false).type() == typeid(double)) doubleTexts_[joinPath(path)] = valueText;
    else doubleTexts_.erase(joinPath(path));
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
    } else if (const auto bad = invalid_.find(joinPath(path)); bad != invalid_.end()) {
      const SpecValidator *spec = specOf(*declared);
      throw DeckError(where(path) + ": " + bad->second + (spec ? "; allowed: " + spec->allowed() : std::string()));
    } else if (const SpecValidator *spec = specOf(*declared)) {
      std::string why = spec->check(entry);
      const auto text = doubleTexts_.find(joinPath(path));
      if (why.empty() && text != doubleTexts_.end() && entry.getAny(false).type() == typeid(double))
        why = spec->checkText(Teuchos::any_cast<double>(entry.getAny(false)), text->second);
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
