#pragma once
// A prescribed quantity written in the deck as an expression of the reference position X, Y, Z [m]
// and the time t [s], e.g. "(1.2 * t) * X" for a radial displacement that grows linearly in time.
// Teuchos' MathExpr reads it: + - * / ^ (power), parentheses, sqrt, exp, log, sin, cos, tan, abs
// and the comparisons with ?: (e.g. "t < 0.5 ? 2 * t : 1"). It is checked when it is built (its
// syntax, and that it names no variable but X, Y, Z and t) and evaluated by parsing it again with
// the values assigned: a few microseconds, for the nodes of a condition once per evaluation.
// The interface is free of Teuchos, so the scene and the assembly need no parser headers.

#include <memory>
#include <string>

namespace glossa::io {

class SpaceTimeExpression {
public:
  // Throws std::invalid_argument with the reason (the parser's message, or the unknown names).
  explicit SpaceTimeExpression(std::string text);
  ~SpaceTimeExpression();
  SpaceTimeExpression(const SpaceTimeExpression &) = delete;
  SpaceTimeExpression &operator=(const SpaceTimeExpression &) = delete;

  double operator()(double X, double Y, double Z, double t) const;
  const std::string &text() const { return text_; }

private:
  struct Parser;
  std::string text_;
  std::unique_ptr<Parser> parser_;
};

} // namespace glossa::io
