#pragma once
// Declaring deck parameters: every object states its parameters with a default, a unit, a doc
// string and an allowed range (doc/developing.md: values are validated, never guessed). The
// declarations are the single source of the validation, of `glossa validate` and of
// doc/deck-reference.md.

#include <limits>
#include <string>
#include <vector>

#include <Teuchos_Array.hpp>
#include <Teuchos_ParameterEntryValidator.hpp>
#include <Teuchos_ParameterList.hpp>

namespace glossa::io {

// Bounds of a numeric parameter; each end may be open (excluded) or closed (included).
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool loOpen = false;
  bool hiOpen = false;

  static Range any() { return {}; }
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range nonNegative() { return {0.0, std::numeric_limits<double>::infinity(), false, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range open(double a, double b) { return {a, b, true, true}; }
  static Range atLeast(double a) { return {a, std::numeric_limits<double>::infinity(), false, false}; }

  bool contains(double v) const;
  std::string describe(const std::string &unit) const; // e.g. "-1 < value < 0.5"
};

// Name under which a repeated sublist's template is declared: every user sublist at that level
// (e.g. each boundary condition) is validated against it.
inline const char *const kAnySublist = "*";

void declareDouble(Teuchos::ParameterList &list, const std::string &name, double defaultValue,
                   const std::string &unit, const std::string &doc, Range range = Range::any());
void declareInt(Teuchos::ParameterList &list, const std::string &name, int defaultValue,
                const std::string &doc, Range range = Range::any());
void declareBool(Teuchos::ParameterList &list, const std::string &name, bool defaultValue,
                 const std::string &doc);
void declareString(Teuchos::ParameterList &list, const std::string &name,
                   const std::string &defaultValue, const std::string &doc,
                   const std::vector<std::string> &allowed = {});
// Fixed-size (size > 0) or any-size (size = 0) arrays, every entry in `range`.
void declareDoubleArray(Teuchos::ParameterList &list, const std::string &name,
                        const Teuchos::Array<double> &defaultValue, const std::string &unit,
                        const std::string &doc, int size, Range range = Range::any());
void declareIntArray(Teuchos::ParameterList &list, const std::string &name,
                     const Teuchos::Array<int> &defaultValue, const std::string &doc, int size,
                     Range range = Range::any());

// The unit a parameter was declared with ("" if none) and its description.
std::string unitOf(const Teuchos::ParameterEntry &entry);
std::string allowedOf(const Teuchos::ParameterEntry &entry);

} // namespace glossa::io
