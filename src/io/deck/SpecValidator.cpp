#include "io/deck/SpecValidator.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Teuchos_Array.hpp>
#include <Teuchos_StrUtils.hpp>

#include "io/deck/StrictNumber.hpp"

namespace glossa::io {

namespace {
std::string joined(const std::vector<std::string> &words) {
  std::string out;
  for (const auto &w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

// The shortest text that reads back as `v` (0.49999999999999 is not shown as 0.5).
std::string exact(double v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
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

std::string SpecValidator::checkText(double v, const std::string &text) const {
  const bool atLo = std::isfinite(range_.lo) && v == range_.lo, atHi = std::isfinite(range_.hi) && v == range_.hi;
  if (kind_ != Kind::Double || !(atLo || atHi) || sameDecimalValue(text, exact(v))) return "";
  const double inside = std::nextafter(v, atLo ? range_.hi : range_.lo);
  return "= '" + text + "' is read as " + exact(v) +
         " (the nearest double), the bound of its range, which the text is not; write " + exact(v) +
         " if that is meant, or a value a double tells apart from it (the nearest inside: " + exact(inside) + ")";
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
    return range_.contains(v) ? "" : "= " + exact(v) + " is out of range";
  }
  case Kind::Int: {
    if (value.type() != typeid(int)) return typeError("int (type=\"int\")");
    const int v = Teuchos::any_cast<int>(value);
    return range_.contains(v) ? "" : "= " + std::to_string(v) + " is out of range";
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
    for (int i = 0; i < a.size(); ++i)
      if (!range_.contains(a[i])) return "has entry " + std::to_string(i + 1) + " = " + exact(a[i]) + " out of range";
    return "";
  }
  case Kind::IntArray: {
    if (value.type() != typeid(Teuchos::Array<int>))
      return typeError("an array of integers (type=\"Array(int)\", value=\"{1, 2, 3}\")");
    const auto &a = Teuchos::any_cast<Teuchos::Array<int>>(value);
    if (arraySize_ > 0 && a.size() != arraySize_)
      return "has " + std::to_string(a.size()) + " entries";
    for (int i = 0; i < a.size(); ++i)
      if (!range_.contains(a[i])) return "has entry " + std::to_string(i + 1) + " = " + std::to_string(a[i]) + " out of range";
    return "";
  }
  }
  return "";
}

Teuchos::ParameterEntry SpecValidator::parse(const std::string &text) const {
  Teuchos::ParameterEntry entry;
  switch (kind_) {
  case Kind::Double: entry.setValue(parseStrictDouble(text)); break;
  case Kind::Int: entry.setValue(parseStrictInt(text)); break;
  case Kind::Bool: entry.setValue(parseStrictBool(text)); break;
  case Kind::String: entry.setValue(text); break;
  case Kind::DoubleArray: {
    const auto v = parseStrictDoubleArray(text, false);
    entry.setValue(Teuchos::Array<double>(v.begin(), v.end()));
    break;
  }
  case Kind::IntArray: {
    const auto v = parseStrictIntArray(text, false);
    entry.setValue(Teuchos::Array<int>(v.begin(), v.end()));
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
