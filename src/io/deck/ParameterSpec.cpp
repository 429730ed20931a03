#include "io/deck/ParameterSpec.hpp"

#include <cmath>
#include <sstream>

#include <Teuchos_RCP.hpp>

#include "io/deck/SpecValidator.hpp"

namespace glossa::io {

namespace {
std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

Teuchos::RCP<SpecValidator> spec(SpecValidator::Kind kind, const std::string &unit, Range range,
                                 std::vector<std::string> allowed = {}, int size = 0) {
  return Teuchos::rcp(new SpecValidator(kind, unit, range, std::move(allowed), size));
}
} // namespace

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false; // no parameter means infinity or NaN
  const bool aboveLo = loOpen ? v > lo : v >= lo;
  const bool belowHi = hiOpen ? v < hi : v <= hi;
  return aboveLo && belowHi;
}

std::string Range::describe(const std::string &unit) const {
  const bool hasLo = std::isfinite(lo);
  const bool hasHi = std::isfinite(hi);
  std::string text;
  if (!hasLo && !hasHi) text = "any value";
  else if (hasLo && hasHi)
    text = number(lo) + (loOpen ? " < " : " <= ") + "value" + (hiOpen ? " < " : " <= ") + number(hi);
  else if (hasLo) text = std::string("value ") + (loOpen ? "> " : ">= ") + number(lo);
  else text = std::string("value ") + (hiOpen ? "< " : "<= ") + number(hi);
  if (!unit.empty()) text += " [" + unit + "]";
  return text;
}

void declareDouble(Teuchos::ParameterList &list, const std::string &name, double defaultValue,
                   const std::string &unit, const std::string &doc, Range range) {
  list.set(name, defaultValue, doc, spec(SpecValidator::Kind::Double, unit, range));
}

void declareInt(Teuchos::ParameterList &list, const std::string &name, int defaultValue,
                const std::string &doc, Range range) {
  list.set(name, defaultValue, doc, spec(SpecValidator::Kind::Int, "", range));
}

void declareBool(Teuchos::ParameterList &list, const std::string &name, bool defaultValue,
                 const std::string &doc) {
  list.set(name, defaultValue, doc, spec(SpecValidator::Kind::Bool, "", Range::any()));
}

void declareString(Teuchos::ParameterList &list, const std::string &name,
                   const std::string &defaultValue, const std::string &doc,
                   const std::vector<std::string> &allowed) {
  list.set(name, defaultValue, doc, spec(SpecValidator::Kind::String, "", Range::any(), allowed));
}

void declareDoubleArray(Teuchos::ParameterList &list, const std::string &name,
                        const Teuchos::Array<double> &defaultValue, const std::string &unit,
                        const std::string &doc, int size, Range range) {
  list.set(name, defaultValue, doc,
           spec(SpecValidator::Kind::DoubleArray, unit, range, {}, size));
}

void declareIntArray(Teuchos::ParameterList &list, const std::string &name,
                     const Teuchos::Array<int> &defaultValue, const std::string &doc, int size,
                     Range range) {
  list.set(name, defaultValue, doc, spec(SpecValidator::Kind::IntArray, "", range, {}, size));
}

std::string unitOf(const Teuchos::ParameterEntry &entry) {
  auto v = Teuchos::rcp_dynamic_cast<const SpecValidator>(entry.validator());
  return v.is_null() ? std::string() : v->unit();
}

std::string allowedOf(const Teuchos::ParameterEntry &entry) {
  auto v = Teuchos::rcp_dynamic_cast<const SpecValidator>(entry.validator());
  return v.is_null() ? std::string() : v->allowed();
}

} // namespace glossa::io
