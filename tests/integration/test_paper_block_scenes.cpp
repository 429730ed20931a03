// The behaviour the paper reports for its §7.1 muscle block, checked on the traces of the runs
// the regression tests make of the decks (ctest runs them first, as fixtures; they also match
// them against the stored tests/regression/s7_1_*.csv):
//  (a) e1 and e3 fibres contract: the e1 and e3 faces move in and, the block being
//      incompressible, the top face rises; at the end (1 + u_e1)(1 + u_top)(1 + u_e3) = 1 for
//      the homogeneous deformation within 1e-3;
//  (b), (c) the external muscle lifts the top face; with origins spread twice as wide (cs = 2)
//      the top corner P moves outwards, where with cs = 1 it is drawn in by incompressibility.
#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {
std::map<std::string, std::array<double, 3>> finalRow(const std::string &stem) {
  const std::string file = std::string(GLOSSA_BINARY_DIR) + "/test-output/regression/" + stem + "/traces.csv";
  const auto rows = test::readTraces(file);
  std::map<std::string, std::array<double, 3>> out;
  EXPECT_FALSE(rows.empty()) << file << ": run ctest -R regression." << stem << " first";
  if (rows.empty()) return out;
  const double last = rows.back().time;
  EXPECT_NEAR(last, 0.5, 1e-12);
  for (const auto &r : rows)
    if (r.time == last) out[r.point] = {r.u[0], r.u[1], r.u[2]};
  return out;
}
} // namespace

TEST(PaperBlockScenes, InternalFibresE1E3LiftTheTopFace) {
  const auto u = finalRow("s7_1_a_internal");
  const double L = 1e-3;
  EXPECT_LT(u.at("e1 face")[0], -0.1 * L);
  EXPECT_LT(u.at("e3 face")[2], -0.1 * L);
  EXPECT_GT(u.at("top centre")[1], 0.2 * L);
  const double volume = (1 + u.at("e1 face")[0] / L) * (1 + u.at("top centre")[1] / L) * (1 + u.at("e3 face")[2] / L);
  EXPECT_NEAR(volume, 1.0, 1e-3);
  EXPECT_NEAR(u.at("e1 face")[0], u.at("e3 face")[2], 1e-6 * L); // symmetric in e1, e3
}

TEST(PaperBlockScenes, WiderExternalOriginsPullTheTopFaceOutwards) {
  const auto b = finalRow("s7_1_b_external_cs1"), c = finalRow("s7_1_c_external_cs2");
  const double L = 1e-3;
  EXPECT_GT(b.at("top centre")[1], 0.2 * L);
  EXPECT_GT(c.at("top centre")[1], 0.1 * L);
  EXPECT_LT(b.at("P")[0], 0.0);  // cs = 1: drawn in
  EXPECT_GT(c.at("P")[0], 0.0);  // cs = 2: pulled out
  EXPECT_GT(c.at("P")[0] - b.at("P")[0], 0.2 * L);
}

// Newton stays quadratic with the external muscle's tangent (case (b), first 20 ms, the muscle
// activating): e_{k+1} <= 10 e_k^2 for e = |f| / |f_0| in the first solve of each step, once
// e < 1e-2 and above round-off.
TEST(PaperBlockScenes, NewtonIsQuadraticWithTheExternalMuscle) {
  const auto s = test::runDeck(test::inputPath("paper/s7_1_b_external_cs1.xml"),
                               {"Time/end time=0.02", "Linear solver/tolerance=1e-10",
                                "Nonlinear solver/forcing term=constant"},
                               test::scratchDirectory("s7_1_b_newton"));
  ASSERT_TRUE(s.at("converged").get<bool>());
  EXPECT_GE(test::expectQuadraticNewton(s), 3);
}
