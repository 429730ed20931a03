// SpaceTimeExpression: a prescribed displacement written as an expression of X, Y, Z and t,
// against the same arithmetic in C++; its errors name what is wrong before a run starts.

#include <gtest/gtest.h>

#include <cmath>

#include "io/deck/SpaceTimeExpression.hpp"

namespace glossa::io {
namespace {

TEST(SpaceTimeExpression, EvaluatesLikeTheSameArithmetic) {
  const SpaceTimeExpression radial("1.2 * t * X");
  const SpaceTimeExpression mixed("sqrt(X^2 + Y^2) * exp(-t) + sin(Z) - (t < 0.5 ? 2 * t : 1)");
  const double points[][4] = {{1e-3, 0.0, 0.0, 0.25}, {-7.0710678118654757e-4, 6.123233995736766e-20, 2e-3, 0.75},
                              {3.3e-12, -1e-9, 1e5, 1e-7}, {0.0, -0.0, 0.5, 0.0}};
  for (const auto &p : points) {
    const double X = p[0], Y = p[1], Z = p[2], t = p[3];
    // MathExpr reads its decimal constants to within a few ulps.
    EXPECT_NEAR(radial(X, Y, Z, t), 1.2 * t * X, 1e-14 * std::abs(X) + 1e-300);
    const double expected = std::sqrt(X * X + Y * Y) * std::exp(-t) + std::sin(Z) - (t < 0.5 ? 2 * t : 1);
    EXPECT_NEAR(mixed(X, Y, Z, t), expected, 1e-13 * (1.0 + std::abs(expected)));
  }
}

TEST(SpaceTimeExpression, RefusesUnknownNamesAndBadSyntaxWithTheReason) {
  auto message = [](const std::string &text) {
    try {
      SpaceTimeExpression e(text);
    } catch (const std::invalid_argument &e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("x * t + q").find("names q, x; an expression may name X, Y, Z"), std::string::npos) << message("x * t + q");
  EXPECT_NE(message("X + ").find("is not an expression: Parser failure at line 1 column 5"), std::string::npos) << message("X + ");
  EXPECT_NE(message("foo(X)").find("Unknown unary function name \"foo\""), std::string::npos) << message("foo(X)");
  EXPECT_NE(message("X < 1 ? 2").find("is not an expression"), std::string::npos);
}

} // namespace
} // namespace glossa::io
