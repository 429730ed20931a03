// A converged state with an element folded through itself is not a result (doc/theory.md,
// "Folded elements"): the run stops at the first such state, naming the element, where it is and
// when, and every step it accepted keeps its elements' turned-over volume below the threshold.
// The step-44 block at 4^3 with nu = 0.4999999 under ten times its load folds cubes that were
// regular; the sound tongue scene s8_4_sg, whose near-degenerate imaged corners turn over to det F
// = -8.5, runs to its end. Each fold is checked against the element-level measure of the state
// itself (tests/unit/fem/test_turned_over_volume.cpp checks that measure against quadrature).
#include <gtest/gtest.h>

#include "RunDeck.hpp"
#include "fem/TurnedOverVolume.hpp"

using namespace glossa;

namespace {
constexpr double kFoldedFraction = 0.0025; // fem::kFoldedFraction, the documented threshold

// Every accepted step below the threshold; returns the largest.
double largestTurnedOver(const nlohmann::json &summary) {
  double largest = 0.0;
  for (const auto &step : summary.at("steps")) {
    const double v = step.at("max_turned_over_volume");
    EXPECT_LE(v, kFoldedFraction) << "t = " << step.at("time");
    largest = std::max(largest, v);
  }
  return largest;
}
} // namespace

TEST(FoldedElements, TheStep44BlockUnderTenTimesItsLoadStopsAtItsFirstFold) {
  const auto output = test::scratchDirectory("folded_block");
  const auto s = test::runDeck(test::inputPath("verification/step44_block.xml"),
                               {"Mesh/Box/cells=4,4,4", "Material/Poisson's ratio=0.4999999",
                                "Loads/pressure patch/traction={0, -4e9, 0}"},
                               output);
  EXPECT_FALSE(s.at("converged").get<bool>());
  ASSERT_TRUE(s.contains("folded_element")) << s.value("failure", "");
  const auto &fold = s.at("folded_element");
  EXPECT_GT(fold.at("turned_over_volume").get<double>(), kFoldedFraction);
  EXPECT_LT(fold.at("min_corner_J").get<double>(), 0.0);
  // The element's reference centroid is that of a cube of the 4^3 block (0.25 mm cells).
  const std::size_t e = fold.at("element");
  const double h = 0.25e-3;
  const std::size_t i = e % 4, j = (e / 4) % 4, k = e / 16;
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(fold.at("reference_centroid")[c].get<double>(), h * (0.5 + (c == 0 ? i : c == 1 ? j : k)), 1e-12);
  // It stopped there: the fold is after the last accepted step, and the failure names it.
  const double lastAccepted = s.at("steps").back().at("time");
  EXPECT_GT(fold.at("time").get<double>(), lastAccepted);
  const std::string failure = s.at("failure");
  EXPECT_NE(failure.find("element " + std::to_string(e) + " "), std::string::npos) << failure;
  EXPECT_NE(failure.find("folded through itself"), std::string::npos) << failure;
  EXPECT_GT(largestTurnedOver(s), 0.0); // the fold grew over the accepted steps
}

TEST(FoldedElements, TheSoundTongueSceneWithTurnedOverCornersRunsToItsEnd) {
  const auto output = test::scratchDirectory("folded_sound_tongue");
  const auto s = test::runDeck(test::inputPath("paper/s8_4_sg.xml"), {}, output);
  ASSERT_TRUE(s.at("converged").get<bool>()) << s.value("failure", "");
  EXPECT_FALSE(s.contains("folded_element"));
  double smallestCorner = 1.0;
  for (const auto &step : s.at("steps")) smallestCorner = std::min(smallestCorner, step.at("min_corner_J").get<double>());
  EXPECT_LT(smallestCorner, -5.0); // corners turned over far beyond a folded cube's -0.5 (-8.5 measured)
  EXPECT_LT(largestTurnedOver(s), 0.6 * kFoldedFraction); // 0.139 % measured
}
