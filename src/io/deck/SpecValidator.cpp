#include "io/deck/SpecValidator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Teuchos_Array.hpp>
#include <Teuchos_StrUtils.hpp>

namespace glossa::io {

namespace {
std::string joined(const std::vector<std::string> &words) {
  std::string out;
  for (const auto &w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

std::vector<std::string> splitCommas(const std::string &text) {
  std::string inner = text;
  // Accept both "1,2,3" and Teuchos' own "{1, 2, 3}".
  inner.erase(std::remove_if(inner.begin(), inner.end(),
                             [](char c) { return c == '{' || c == '}' || std::isspace(c); }),
              inner.end());
  std::vector<std::string> parts;
  std::stringstream s(inner);
  std::string item;
  while (std::getline(s, item, ',')) parts.push_back(item);
  return parts;
}

double parseDouble(const std::string &text) {
  std::size_t used = 0;
  const double v = std::stod(text, &used);
  if (used != text.size()) throw std::invalid_argument("'" + text + "' is not a number");
  return v;
}

int parseInt(const std::string &text) {
  std::size_t used = 0;
  const int v = std::stoi(text, &used);
  if (used != text.size()) throw std::invalid_argument("'" + text + "' is not an integer");
  return v;
}
} // namespace

SpecValidator::SpecValidator(Kind kind, std::string unit, Range range,
                             std::vector<std::string> allowed, int arraySize)
    : kind_(kind), unit_(std::move(unit)), range_(range), allowedWords_(std::move(allowed)),
      arraySize_(arraySize) {}

std::string SpecValidator::allowed() const {
  const std::string sizeText =
      arraySize_ > 0 ? std::to_string(arraySize_) + " entries" : "any number of entries";
  switch (kind_) {
  case Kind::Double: return "real number, " + range_.describe(unit_);
  case Kind::Int: return "integer, " + range_.describe(unit_);
  case Kind::Bool: return "true or false";
  case Kind::String:
    return allowedWords_.empty() ? std::string("any text") : "one of: " + joined(allowedWords_);
  case Kind::DoubleArray: return "array of real numbers (" + sizeText + "), each " + range_.describe(unit_);
  case Kind::IntArray: return "array of integers (" + sizeText + "), each " + range_.describe(unit_);
  }
  return "";
}

std::string SpecValidator::check(const Teuchos::ParameterEntry &entry) const {
  const Teuchos::any &value = entry.getAny(false);
  auto typeError = [&](const std::string &expected) {
    return "has type " + entry.getAny(false).typeName() + " but must be " + expected;
  };
  switch (kind_) {
  case Kind::Double: {
    if (value.type() != typeid(double)) return typeError("double (type=\"double\")");
    const double v = Teuchos::any_cast<double>(value);
    if (!range_.contains(v)) {
      std::ostringstream text;
      text << "= " << v << " is out of range";
      return text.str();
    }
    return "";
  }
  case Kind::Int: {
    if (value.type() != typeid(int)) return typeError("int (type=\"int\")");
    if (!range_.contains(Teuchos::any_cast<int>(value))) return "is out of range";
    return "";
  }
  case Kind::Bool:
    return value.type() == typeid(bool) ? "" : typeError("bool (type=\"bool\")");
  case Kind::String: {
    if (value.type() != typeid(std::string)) return typeError("string (type=\"string\")");
    const auto &v = Teuchos::any_cast<std::string>(value);
    if (!allowedWords_.empty() &&
        std::find(allowedWords_.begin(), allowedWords_.end(), v) == allowedWords_.end())
      return "= '" + v + "' is not an allowed word";
    return "";
  }
  case Kind::DoubleArray: {
    if (value.type() != typeid(Teuchos::Array<double>))
      return typeError("an array of doubles (type=\"Array(double)\", value=\"{1, 2, 3}\")");
    const auto &a = Teuchos::any_cast<Teuchos::Array<double>>(value);
    if (arraySize_ > 0 && a.size() != arraySize_)
      return "has " + std::to_string(a.size()) + " entries";
    for (double v : a)
      if (!range_.contains(v)) return "has an entry out of range";
    return "";
  }
  case Kind::IntArray: {
    if (value.type() != typeid(Teuchos::Array<int>))
      return typeError("an array of integers (type=\"Array(int)\", value=\"{1, 2, 3}\")");
    const auto &a = Teuchos::any_cast<Teuchos::Array<int>>(value);
    if (arraySize_ > 0 && a.size() != arraySize_)
      return "has " + std::to_string(a.size()) + " entries";
    for (int v : a)
      if (!range_.contains(v)) return "has an entry out of range";
    return "";
  }
  }
  return "";
}

Teuchos::ParameterEntry SpecValidator::parse(const std::string &text) const {
  Teuchos::ParameterEntry entry;
  switch (kind_) {
  case Kind::Double: entry.setValue(parseDouble(text)); break;
  case Kind::Int: entry.setValue(parseInt(text)); break;
  case Kind::Bool:
    if (text == "true" || text == "1") entry.setValue(true);
    else if (text == "false" || text == "0") entry.setValue(false);
    else throw std::invalid_argument("'" + text + "' is not true or false");
    break;
  case Kind::String: entry.setValue(text); break;
  case Kind::DoubleArray: {
    Teuchos::Array<double> a;
    for (const auto &p : splitCommas(text)) a.push_back(parseDouble(p));
    entry.setValue(a);
    break;
  }
  case Kind::IntArray: {
    Teuchos::Array<int> a;
    for (const auto &p : splitCommas(text)) a.push_back(parseInt(p));
    entry.setValue(a);
    break;
  }
  }
  return entry;
}

void SpecValidator::printDoc(const std::string &docString, std::ostream &out) const {
  out << "# " << docString << "\n# allowed: " << allowed() << "\n";
}

Teuchos::ParameterEntryValidator::ValidStringsList SpecValidator::validStringValues() const {
  if (allowedWords_.empty()) return Teuchos::null;
  return Teuchos::rcp(new Teuchos::Array<std::string>(allowedWords_.begin(), allowedWords_.end()));
}

void SpecValidator::validate(const Teuchos::ParameterEntry &entry, const std::string &paramName,
                             const std::string &sublistName) const {
  const std::string why = check(entry);
  if (!why.empty())
    throw Teuchos::Exceptions::InvalidParameterValue(sublistName + "->" + paramName + " " + why +
                                                     "; allowed: " + allowed());
}

} // namespace glossa::io
