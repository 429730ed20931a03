// The GA controller through the full solve (inputs/paper/s7_2_ga.xml, first 3 control steps):
// the same seed gives the same run (inputs, objectives, trace, bit for bit); the controlled
// corner P stays within 20 % of the passive run's peak displacement (the passive trace is
// tests/regression/s7_2_passive.csv); and the e2 family, the one the lateral
// compression stretches, is the one the controller contracts (paper §7.2). The measure of success:
// P within a fraction of the passive run's peak displacement (aim: under 20 %). And on the
// controlled tongue, where the GA's candidates start (Control/predicted start).
#include <cmath>

#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {
nlohmann::json runControlled(const std::string &tag) {
  return test::runDeck(test::inputPath("paper/s7_2_ga.xml"), {"Time/end time=0.15"}, test::scratchDirectory(tag));
}
} // namespace

TEST(GeneticAlgorithmControl, ReproducibleAndHoldsTheCorner) {
  const auto a = runControlled("control_a"), b = runControlled("control_b");
  ASSERT_TRUE(a.at("converged").get<bool>());
  ASSERT_EQ(a.at("steps").size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(a.at("steps")[k].at("control"), b.at("steps")[k].at("control")) << "step " << k;
    EXPECT_GE(a.at("steps")[k].at("control").at("candidates").get<int>(), 1);
  }
  EXPECT_EQ(a.at("final_displacement"), b.at("final_displacement"));

  // The passive run's peak displacement of P, from the stored passive trace.
  const double passivePeak =
      test::peakDisplacement(std::string(GLOSSA_SOURCE_DIR) + "/tests/regression/s7_2_passive.csv", "P");
  ASSERT_GT(passivePeak, 1e-4);
  const auto u = a.at("final_displacement").at("P").get<std::vector<double>>();
  EXPECT_LT(std::hypot(u[0], std::hypot(u[1], u[2])), 0.2 * passivePeak);

  // The first step prunes everything (nothing is stretched yet); once the side pressure has
  // stretched e2, the controller drives it (at the third step: one step of full activation
  // at the second would overshoot the still small load).
  const auto &first = a.at("steps")[0].at("control");
  for (const auto &[group, input] : first.at("inputs").items()) EXPECT_EQ(input.get<double>(), 0.0) << group;
  const auto &third = a.at("steps")[2].at("control").at("inputs");
  EXPECT_EQ(third.at("e2").get<double>(), 1.0);
  EXPECT_EQ(third.at("e1").get<double>(), 0.0);
  EXPECT_EQ(third.at("e3").get<double>(), 0.0);
}

// The GA's candidates start from its Gauss-Newton seed's solve moved along that state's
// responses (doc/control.md, "Where a candidate starts"), or, with predicted start = false, from
// the step's start. On the supine tongue's first two control steps (3 generations, 29 and 33
// candidates) the two searches find the same winners to the Uzawa loop's tolerance (a dilatation
// error of 1e-3), the predicted starts with fewer element passes and substitutions (measured
// 2026-12-06: 639 against 844 passes, 2,306 against 3,309 substitutions; 30 s against 49 s).
TEST(GeneticAlgorithmControl, SeedStartsSaveSolvesNotAccuracy) {
  auto run = [](const std::string &predicted) {
    return test::runDeck(test::inputPath("paper/s8_5_ga_supine.xml"),
                         {"Time/end time=0.625", "Control/generations=3", "Output/fields=false",
                          "Control/predicted start=" + predicted, "Control/retry turned-over starts=true"},
                         test::scratchDirectory("ga_tongue_start_" + predicted));
  };
  const auto predicted = run("true"), fromStepStart = run("false");
  ASSERT_TRUE(predicted.at("converged").get<bool>());
  ASSERT_TRUE(fromStepStart.at("converged").get<bool>());
  auto passes = [](const nlohmann::json &r) { return r.at("residual_evaluations").get<double>(); };
  auto substitutions = [](const nlohmann::json &r) {
    return r.at("time_split").at("direct_solve").at("calls").get<double>();
  };
  EXPECT_LT(passes(predicted), 0.85 * passes(fromStepStart));
  EXPECT_LT(substitutions(predicted), 0.8 * substitutions(fromStepStart));
  for (std::size_t k = 0; k < 2; ++k) {
    const auto &a = predicted.at("steps").at(k).at("control"), &b = fromStepStart.at("steps").at(k).at("control");
    const double objective = b.at("objective").get<double>();
    EXPECT_NEAR(a.at("objective").get<double>(), objective, 1e-3 * objective) << "step " << k;
    for (const auto &[group, input] : b.at("inputs").items())
      EXPECT_NEAR(a.at("inputs").at(group).get<double>(), input.get<double>(), 1e-3) << group << ", step " << k;
  }
}

// Control/retry turned-over starts = false (the s8_5 GA decks): a candidate whose moved start
// turns an element over is ranked as failed instead of solved again from the step's start. On
// the supine tongue's first control step (3 generations, 29 candidates) 14 of them are screened,
// the step takes 38 factorisations against 84 and 129 element passes against 274, and its winner
// is 1.8 % further from the goals (7.41 against 7.28 mm, measured 2026-12-07): the search differs
// from the first screened candidate on, so the bound is on the objective, not the inputs.
TEST(GeneticAlgorithmControl, ScreenedStartsSaveSolves) {
  auto run = [](const std::string &retry) {
    return test::runDeck(test::inputPath("paper/s8_5_ga_supine.xml"),
                         {"Time/end time=0.3125", "Control/generations=3", "Output/fields=false",
                          "Control/retry turned-over starts=" + retry},
                         test::scratchDirectory("ga_tongue_retry_" + retry));
  };
  const auto screened = run("false"), retried = run("true");
  ASSERT_TRUE(screened.at("converged").get<bool>());
  ASSERT_TRUE(retried.at("converged").get<bool>());
  const auto &s = screened.at("steps").at(0).at("control"), &r = retried.at("steps").at(0).at("control");
  EXPECT_FALSE(r.contains("screened_candidates"));
  const auto count = s.at("screened_candidates").get<std::size_t>();
  EXPECT_GT(count, 0u);
  EXPECT_LE(count, s.at("failed_candidates").get<std::size_t>());
  auto factorisations = [](const nlohmann::json &run) {
    return run.at("time_split").at("direct_factorisation").at("calls").get<double>();
  };
  EXPECT_LT(factorisations(screened), 0.7 * factorisations(retried));
  EXPECT_LT(screened.at("residual_evaluations").get<double>(), 0.7 * retried.at("residual_evaluations").get<double>());
  const double objective = r.at("objective").get<double>();
  EXPECT_LT(s.at("objective").get<double>(), 1.05 * objective);
}
