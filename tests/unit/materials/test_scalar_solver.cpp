#include <gtest/gtest.h>

#include <cmath>

#include "materials/BracketedNewtonSolver.hpp"

using namespace glossa::materials;

TEST(BracketedNewtonSolver, ConvergesQuadraticallyOnASmoothRoot) {
  const BracketedNewtonSolver solver;
  const auto r = solver.solve([](double x) { return ValueSlope{x * x * x - 2.0, 3 * x * x}; }, 0.0, 2.0, 1.5);
  EXPECT_EQ(r.status, ScalarSolveStatus::Converged);
  EXPECT_NEAR(r.x, std::cbrt(2.0), 1e-15);
  EXPECT_LE(r.iterations, 8);
}

// Newton alone diverges on atan from x0 = 3 (|x| grows); the bracket keeps it safe.
TEST(BracketedNewtonSolver, SafeguardsAgainstNewtonDivergence) {
  const BracketedNewtonSolver solver;
  const auto r = solver.solve(
      [](double x) {
        return ValueSlope{std::atan(x), 1 / (1 + x * x)};
      },
      -5.0, 10.0, 3.0);
  EXPECT_EQ(r.status, ScalarSolveStatus::Converged);
  EXPECT_NEAR(r.x, 0.0, 1e-14);
  // A zero slope forces bisection and still converges.
  const auto flat = solver.solve([](double x) { return ValueSlope{x - 0.25, 0.0}; }, 0.0, 1.0, 0.5);
  EXPECT_EQ(flat.status, ScalarSolveStatus::Converged);
  EXPECT_NEAR(flat.x, 0.25, 1e-14);
}

TEST(BracketedNewtonSolver, ReportsWhyItFails) {
  const BracketedNewtonSolver solver;
  auto line = [](double x) { return ValueSlope{x - 3.0, 1.0}; };
  EXPECT_EQ(solver.solve(line, 0.0, 1.0, 0.5).status, ScalarSolveStatus::InvalidBracket);
  EXPECT_EQ(solver.solve(line, 1.0, 0.0, 0.5).status, ScalarSolveStatus::InvalidBracket);
  EXPECT_EQ(solver.solve(
                      [](double) {
                        return ValueSlope{NAN, 1.0};
                      },
                      0.0, 1.0, 0.5)
                .status,
            ScalarSolveStatus::NonFinite);
  EXPECT_EQ(solver.solve(line, 0.0, INFINITY, 0.5).status, ScalarSolveStatus::NonFinite);
  // NaN only inside the bracket.
  EXPECT_EQ(solver
                .solve(
                    [](double x) {
                      return ValueSlope{x > 0.4 && x < 0.6 ? NAN : x - 0.5, 1.0};
                    },
                    0.0, 1.0, 0.5)
                .status,
            ScalarSolveStatus::NonFinite);
  // A jump through zero: the bracket collapses onto it, the residual stays 1.
  const auto jump = solver.solve(
      [](double x) {
        return ValueSlope{x < 0.3 ? -1.0 : 1.0, 0.0};
      },
      0.0, 1.0, 0.9);
  EXPECT_EQ(jump.status, ScalarSolveStatus::ResidualNotReduced);
  EXPECT_NEAR(jump.x, 0.3, 1e-13);
  ScalarSolveOptions few;
  few.maxIterations = 3;
  EXPECT_EQ(BracketedNewtonSolver(few)
                .solve(
                    [](double x) {
                      return ValueSlope{x - 1e-3, 0.0};
                    },
                    0.0, 1.0, 0.9)
                .status,
            ScalarSolveStatus::MaxIterations);
  for (auto s :
       {ScalarSolveStatus::Converged, ScalarSolveStatus::InvalidBracket, ScalarSolveStatus::NonFinite,
        ScalarSolveStatus::MaxIterations, ScalarSolveStatus::ResidualNotReduced})
    EXPECT_NE(std::string(describe(s)), "?");
}
