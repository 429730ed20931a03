// Cook's membrane: the bending/locking check. Q1-P0's tip displacement converges under
// refinement (successive differences shrink geometrically); a plain Q1 element locks at the
// nearly incompressible limit (its tip moves about a third as far on the same meshes).
#include <cmath>

#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {
double tipDeflection(int n, const std::string &element) {
  const auto summary = test::runDeck(test::inputPath("verification/cook_membrane.xml"),
                                     {"Mesh/Cook membrane/cells per side=" + std::to_string(n), "Material/element=" + element},
                                     test::scratchDirectory("cook_" + element + std::to_string(n)));
  EXPECT_TRUE(summary.at("converged").get<bool>());
  return summary.at("final_displacement").at("tip").at(1).get<double>();
}
} // namespace

TEST(CookMembrane, Q1P0ConvergesUnderRefinement) {
  const double u4 = tipDeflection(4, "Q1P0"), u8 = tipDeflection(8, "Q1P0"), u16 = tipDeflection(16, "Q1P0"),
               u32 = tipDeflection(32, "Q1P0");
  EXPECT_LT(u4, u8);
  EXPECT_LT(u8, u16);
  EXPECT_LT(u16, u32);
  const double d1 = u8 - u4, d2 = u16 - u8, d3 = u32 - u16;
  EXPECT_LT(d2, 0.5 * d1);
  EXPECT_LT(d3, 0.5 * d2);
  // Richardson extrapolation from the two finest meshes: 32 per side is within 1 % of the limit.
  const double order = std::log2(d2 / d3);
  const double limit = u32 + d3 / (std::pow(2.0, order) - 1.0);
  EXPECT_GT(order, 1.0);
  EXPECT_NEAR(u32, limit, 0.01 * limit);
}

TEST(CookMembrane, PlainQ1Locks) {
  for (int n : {4, 8}) {
    const double mixed = tipDeflection(n, "Q1P0"), plain = tipDeflection(n, "Q1");
    EXPECT_GT(plain, 0.0);
    EXPECT_LT(plain, 0.5 * mixed) << n << " elements per side";
  }
}
