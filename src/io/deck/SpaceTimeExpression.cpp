#include "io/deck/SpaceTimeExpression.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include <Teuchos_MathExpr.hpp>

namespace glossa::io {

struct SpaceTimeExpression::Parser {
  std::unique_ptr<Teuchos::Reader> reader{Teuchos::MathExpr::new_calc_reader()};
};

namespace {
// The parser's message without its trace: where it failed and what it expected or did not know.
std::string reason(const std::exception &e) {
  std::string out, line;
  std::istringstream in(e.what());
  while (std::getline(in, line)) {
    const bool useful = line.find("Parser failure") != std::string::npos || line.rfind("Expected", 0) == 0 ||
                        line.rfind("Unknown", 0) == 0 || line.rfind("Got", 0) == 0;
    if (!useful) continue;
    if (line.rfind("error: ", 0) == 0) line.erase(0, 7);
    out += (out.empty() ? "" : "; ") + line;
  }
  return out.empty() ? e.what() : out;
}

// A value as MathExpr reads it: its constants take no "e+20" and read "e-08" wrong, so 6.1e-20
// goes in as (6.1*10^(-20)). (Its decimal reading is not exact either: a value may come back an
// ulp or two off, far below any displacement that matters.)
std::string roundTrip(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", v);
  std::string s = text;
  const auto e = s.find('e');
  if (e == std::string::npos) return "(" + s + ")";
  return "(" + s.substr(0, e) + "*10^(" + std::to_string(std::stoi(s.substr(e + 1))) + "))"; // e-08: "-8"
}
} // namespace

SpaceTimeExpression::SpaceTimeExpression(std::string text) : text_(std::move(text)), parser_(std::make_unique<Parser>()) {
  std::set<std::string> names;
  try {
    names = Teuchos::MathExpr::get_variables_used(text_);
  } catch (const std::exception &e) {
    throw std::invalid_argument("'" + text_ + "' is not an expression: " + reason(e));
  }
  std::string unknown;
  for (const auto &n : names)
    if (n != "X" && n != "Y" && n != "Z" && n != "t") unknown += (unknown.empty() ? "" : ", ") + n;
  if (!unknown.empty())
    throw std::invalid_argument("'" + text_ + "' names " + unknown + "; an expression may name X, Y, Z (the reference position [m]) and t [s]");
  const double probe = (*this)(0.0, 0.0, 0.0, 0.0); // evaluates, so a type error (a bare comparison) shows now
  (void)probe;
}

SpaceTimeExpression::~SpaceTimeExpression() = default;

double SpaceTimeExpression::operator()(double X, double Y, double Z, double t) const {
  const std::string program =
      "X=" + roundTrip(X) + ";Y=" + roundTrip(Y) + ";Z=" + roundTrip(Z) + ";t=" + roundTrip(t) + ";" + text_;
  Teuchos::any result;
  try {
    parser_->reader->read_string(result, program, "expression");
  } catch (const std::exception &e) {
    throw std::invalid_argument("'" + text_ + "' cannot be evaluated: " + reason(e));
  }
  if (result.type() != typeid(double))
    throw std::invalid_argument("'" + text_ + "' is not a number (a comparison needs ?: to give one)");
  return Teuchos::any_cast<double>(result);
}

} // namespace glossa::io
