// The closing-pressure search on a lumen of known closure: two parallel strips 6 mm apart, the
// tongue strip lifted towards the wall as the suction p(t) = -1000 t Pa rises, so that it touches
// the wall, across its whole width, exactly at t_c = 0.3 s, p = -300 Pa. Driven as the run drives
// it (steps of 0.25 s until a trial closes, then steps from the last open state to the bracket's
// middle), the bracket holds -300 Pa and is at most the tolerance wide; a suction that never
// closes the lumen is reported as such.
#include <gtest/gtest.h>

#include <cmath>

#include "airway/AirwayTestShapes.hpp"
#include "solvers/run/PcritSearch.hpp"

using namespace glossa;

namespace {
const double gap = 0.006, tClose = 0.3;

airway::TriangleSet tongueStrip() {
  return airway::test::strip({0, 0, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0.05, -0.02, 0.02);
}

model::AirwayOutput parallelStrips(double tolerance) {
  const airway::TriangleSet tongue = tongueStrip();
  const airway::TriangleSet wall =
      airway::test::strip({0, 0, gap}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0.05, -0.03, 0.03, 7, 9);
  airway::CentrelineSettings c;
  c.start = {0.005, 0, 0};
  c.end = {0.045, 0, 0};
  c.sections = 5;
  model::AirwayOutput out;
  // Only the contact criterion: a section closes when the strips touch across its width.
  out.lumen = std::make_shared<airway::AirwayLumen>(tongue, wall, c, airway::LumenSettings{0.0, 0.0});
  out.pressureTolerance = tolerance;
  return out;
}

// The tongue's vertices at time t: lifted by gap t / t_c (past the wall beyond t_c, as a
// penalty contact's penetration).
std::vector<Eigen::Vector3d> lifted(double t) {
  std::vector<Eigen::Vector3d> x = tongueStrip().vertices;
  for (auto &p : x) p.z() += gap * t / tClose;
  return x;
}

loads::PressureField rampedSuction() {
  return loads::PressureField::uniform(-1000.0, [](double t) { return t; });
}
} // namespace

TEST(PcritSearch, BisectionBracketsTheKnownClosingPressure) {
  const model::AirwayOutput airway = parallelStrips(1.0);
  solvers::PcritSearch search(airway, rampedSuction(), "suction");
  double t = 0.0, dt = 0.25;
  int trials = 0;
  while (!search.found() && trials < 100) {
    ++trials;
    const double trial = t + dt;
    const std::optional<int> section = search.closedSection(lifted(trial));
    if (section) search.closed(trial, *section);
    else search.opened(t = trial);
    if (search.bracketing()) dt = search.nextStep(t);
  }
  ASSERT_TRUE(search.found());
  const nlohmann::json s = search.summary(1.0, 1.0);
  EXPECT_TRUE(s["closed"].get<bool>());
  const double lo = s["low_Pa"], hi = s["high_Pa"];
  EXPECT_LE(lo, -300.0);
  EXPECT_GE(hi, -300.0);
  EXPECT_LE(hi - lo, 1.0);
  EXPECT_NEAR(s["cmH2O"].get<double>() * solvers::kPascalPerCmH2O, s["Pa"].get<double>(), 1e-12);
  EXPECT_NEAR(s["low_cmH2O"].get<double>(), lo / 98.0665, 1e-12);
  // The first bracket [-250, -500] Pa is halved until at most 1 Pa wide: 250 / 2^8 < 1.
  EXPECT_EQ(s["bisection_solves"].get<int>(), 8);
  // The strips are parallel: every section closes at once; the one named is one of them.
  EXPECT_GE(s["section"].get<int>(), 0);
  EXPECT_LT(s["section"].get<int>(), 5);
}

TEST(PcritSearch, ASuctionThatNeverClosesSaysSo) {
  const model::AirwayOutput airway = parallelStrips(1.0);
  solvers::PcritSearch search(airway, rampedSuction(), "suction");
  for (double t = 0.05; t < 0.26; t += 0.05) {
    ASSERT_FALSE(search.closedSection(lifted(t)));
    search.opened(t);
  }
  EXPECT_FALSE(search.bracketing());
  // Stopped at 0.25 s of a deck that ends at 1 s: both suctions said.
  const nlohmann::json s = search.summary(0.25, 1.0);
  EXPECT_FALSE(s["closed"].get<bool>());
  EXPECT_DOUBLE_EQ(s["largest_suction_Pa"].get<double>(), -250.0);
  EXPECT_DOUBLE_EQ(s["deck_largest_suction_Pa"].get<double>(), -1000.0);
  EXPECT_NE(search.line(0.25, 1.0).find("never closed up to -250 Pa"), std::string::npos);
  EXPECT_NE(search.line(0.25, 1.0).find("stopped short"), std::string::npos);
  EXPECT_EQ(search.line(1.0, 1.0).find("stopped short"), std::string::npos);
}
