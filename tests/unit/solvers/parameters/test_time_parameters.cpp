// The Time section's words parsed into enums, and its numbers into the step-size rule.
#include <gtest/gtest.h>

#include "DeckOnFile.hpp"
#include "solvers/parameters/TimeParameters.hpp"

namespace glossa::solvers {
namespace {

TimeParameters parsed(const std::vector<std::string> &overrides) {
  Teuchos::ParameterList schema("Glossa");
  schema.set("Time", timeParameters());
  const io::Deck deck = test::deckOnFile("time.xml", "", schema, overrides);
  return parseTimeParameters(deck.root().sublist("Time"));
}

TEST(TimeParameters, Defaults) {
  const TimeParameters t = parsed({});
  EXPECT_EQ(t.steps.endTime, 1.0);
  EXPECT_EQ(t.steps.nominal, 0.1);
  EXPECT_EQ(t.steps.minimum, 1e-6);
  EXPECT_EQ(t.predictor, Predictor::automatic);
  EXPECT_EQ(t.atLimitPoint, AtLimitPoint::stop);
  EXPECT_EQ(t.limitPointTolerance, 0.01);
  EXPECT_EQ(t.pathFollowing, PathFollowing::loadControl);
  EXPECT_EQ(t.arcLengthSteps, 200);
  EXPECT_EQ(t.stopAtDisplacement, 0.0);
}

TEST(TimeParameters, GivenValues) {
  const TimeParameters t =
      parsed({"Time/end time=3", "Time/step size=0.5", "Time/minimum step size=1e-3", "Time/predictor=linear extrapolation",
              "Time/at a limit point=follow", "Time/limit point tolerance=0.05", "Time/path following=arc length",
              "Time/arc length steps=40", "Time/stop at displacement=0.02"});
  EXPECT_EQ(t.steps.endTime, 3.0);
  EXPECT_EQ(t.steps.nominal, 0.5);
  EXPECT_EQ(t.steps.minimum, 1e-3);
  EXPECT_EQ(t.predictor, Predictor::linearExtrapolation);
  EXPECT_EQ(t.atLimitPoint, AtLimitPoint::follow);
  EXPECT_EQ(t.limitPointTolerance, 0.05);
  EXPECT_EQ(t.pathFollowing, PathFollowing::arcLength);
  EXPECT_EQ(t.arcLengthSteps, 40);
  EXPECT_EQ(t.stopAtDisplacement, 0.02);
}

TEST(TimeParameters, EachWordOfPredictorAndLimitPoint) {
  EXPECT_EQ(parsed({"Time/predictor=none"}).predictor, Predictor::none);
  EXPECT_EQ(parsed({"Time/predictor=auto"}).predictor, Predictor::automatic);
  EXPECT_EQ(parsed({"Time/at a limit point=ignore"}).atLimitPoint, AtLimitPoint::ignore);
  EXPECT_EQ(parsed({"Time/at a limit point=stop"}).atLimitPoint, AtLimitPoint::stop);
}

// A ramp of duration 0 spans the deck's own end time: the file's, or the default where the file
// gives none, whatever --set makes of the run's (a run shortened to 0.3 s shows the first 0.3 s
// of the deck's load history, not all of it).
TEST(TimeParameters, RampsSpanTheDecksOwnEndTime) {
  Teuchos::ParameterList schema("Glossa");
  schema.set("Time", timeParameters());
  const std::string withEnd = "  <ParameterList name=\"Time\">\n    <Parameter name=\"end time\" type=\"double\" "
                              "value=\"2\"/>\n  </ParameterList>\n";
  const io::Deck given = test::deckOnFile("ramp_end.xml", withEnd, schema, {"Time/end time=0.3"});
  EXPECT_EQ(given.root().sublist("Time").get<double>("end time"), 0.3);
  EXPECT_EQ(deckEndTime(given), 2.0);
  EXPECT_EQ(deckEndTime(test::deckOnFile("ramp_end2.xml", withEnd, schema)), 2.0);
  EXPECT_EQ(deckEndTime(test::deckOnFile("ramp_end3.xml", "", schema, {"Time/end time=0.3"})), 1.0);
  EXPECT_EQ(parsed({"Time/end time=3"}).rampEndTime, 3.0); // the section alone knows no file
}

} // namespace
} // namespace glossa::solvers

namespace glossa::solvers {
namespace {

// The dynamic analysis' parameters: defaults (static, rho_inf = 1, consistent mass, no damping,
// at rest), given values, and what a deck is refused for: a value out of its range, a dynamic
// parameter in a static deck, an initial velocity that is not an expression of X, Y, Z.
TEST(TimeParameters, DynamicsDefaultsAndGivenValues) {
  const DynamicsParameters d0 = parsed({}).dynamics;
  EXPECT_FALSE(d0.dynamic());
  EXPECT_EQ(d0.spectralRadius, 1.0);
  EXPECT_EQ(d0.mass, fem::MassLumping::consistent);
  EXPECT_EQ(d0.rayleighMass, 0.0);
  EXPECT_EQ(d0.rayleighStiffness, 0.0);
  EXPECT_EQ(d0.initialVelocity[1], "0");
  const DynamicsParameters d = parsed({"Time/analysis=dynamic", "Time/spectral radius=0.6", "Time/mass matrix=lumped",
                                       "Time/Rayleigh mass coefficient=0.5", "Time/Rayleigh stiffness coefficient=1e-3",
                                       "Time/initial vy=2 * X"})
                                   .dynamics;
  EXPECT_TRUE(d.dynamic());
  EXPECT_EQ(d.spectralRadius, 0.6);
  EXPECT_EQ(d.mass, fem::MassLumping::lumped);
  EXPECT_EQ(d.rayleighMass, 0.5);
  EXPECT_EQ(d.rayleighStiffness, 1e-3);
  EXPECT_EQ(d.initialVelocity[1], "2 * X");
}

TEST(TimeParameters, BadDynamicsParametersAreRefusedWithWhereAndWhatIsAllowed) {
  Teuchos::ParameterList schema("Glossa");
  schema.set("Time", timeParameters());
  const std::string out = test::deckErrorOf([&] { parsed({"Time/spectral radius=1.5"}); });
  EXPECT_NE(out.find("spectral radius"), std::string::npos) << out;
  EXPECT_THROW(parsed({"Time/analysis=implicit"}), std::exception);
  const auto check = [&](const std::string &sections) {
    return test::deckErrorOf([&] {
      const io::Deck deck = test::deckOnFile("dynamics.xml", sections, schema);
      checkDynamicsParameters(deck, parseTimeParameters(deck.root().sublist("Time")).dynamics);
    });
  };
  const std::string staticDeck = check("  <ParameterList name=\"Time\">\n    <Parameter name=\"spectral radius\" "
                                       "type=\"double\" value=\"0.5\"/>\n  </ParameterList>\n");
  EXPECT_NE(staticDeck.find("dynamics.xml:3"), std::string::npos) << staticDeck;
  EXPECT_NE(staticDeck.find("Time/analysis = dynamic"), std::string::npos) << staticDeck;
  const std::string badVelocity =
      check("  <ParameterList name=\"Time\">\n    <Parameter name=\"analysis\" type=\"string\" value=\"dynamic\"/>\n"
            "    <Parameter name=\"initial vz\" type=\"string\" value=\"2 * Q\"/>\n  </ParameterList>\n");
  EXPECT_NE(badVelocity.find("dynamics.xml:4"), std::string::npos) << badVelocity;
  EXPECT_NE(badVelocity.find("X, Y, Z"), std::string::npos) << badVelocity;
  EXPECT_EQ(check("  <ParameterList name=\"Time\">\n    <Parameter name=\"analysis\" type=\"string\" value=\"dynamic\"/>\n"
                  "    <Parameter name=\"initial vz\" type=\"string\" value=\"2 * Y + X\"/>\n  </ParameterList>\n"),
            "");
}

} // namespace
} // namespace glossa::solvers
