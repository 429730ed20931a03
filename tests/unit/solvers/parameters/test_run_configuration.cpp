// The solver-side sections parsed once into RunConfiguration: each section's values (given and
// defaulted), whether a controller is asked for, the deck's listing that a restart compares, the
// Linear solver parameters given that only an iterative solve uses (each with where it was
// given), the direct solve's reuse scope under a coupled airflow, and the first difference
// between two listings.
#include <gtest/gtest.h>

#include "DeckOnFile.hpp"
#include "input/AirflowParameters.hpp"
#include "solvers/parameters/ControlSection.hpp"
#include "solvers/parameters/RunConfiguration.hpp"

namespace glossa::solvers {
namespace {

// The sections RunConfiguration reads, declared as the deck schema declares them.
Teuchos::ParameterList schema() {
  Teuchos::ParameterList s("Glossa");
  s.set("Time", timeParameters());
  s.set("Incompressibility", incompressibilityParameters());
  s.set("Nonlinear solver", nonlinearSolverParameters());
  s.set("Linear solver", linearSolverParameters());
  s.set("Output", outputParameters());
  s.set("Control", controlParameters());
  s.set("Airflow", input::airflowParameters());
  return s;
}

const char *kSections = R"X(<ParameterList name="Time">
  <Parameter name="end time" type="double" value="2"/>
  <Parameter name="predictor" type="string" value="none"/>
</ParameterList>
<ParameterList name="Incompressibility">
  <Parameter name="method" type="string" value="penalty"/>
</ParameterList>
<ParameterList name="Linear solver">
  <Parameter name="tolerance" type="double" value="1e-8"/>
  <Parameter name="MueLu smoother" type="string" value="Chebyshev"/>
</ParameterList>
<ParameterList name="Output">
  <Parameter name="volume face sets" type="string" value="inner , outer"/>
  <Parameter name="checkpoint every" type="int" value="0"/>
</ParameterList>
<ParameterList name="Control">
  <Parameter name="type" type="string" value="gradient"/>
</ParameterList>
)X";

RunConfiguration configuration(const std::string &name, const std::vector<std::string> &overrides = {}) {
  return parseRunConfiguration(test::deckOnFile(name, kSections, schema(), overrides));
}

TEST(RunConfiguration, EachSectionGivenOrDefaulted) {
  const RunConfiguration c = configuration("run_configuration.xml");
  EXPECT_EQ(c.deckFile, test::deckPath("run_configuration.xml"));
  EXPECT_EQ(c.time.steps.endTime, 2.0);
  EXPECT_EQ(c.time.steps.nominal, 0.1);
  EXPECT_EQ(c.time.predictor, Predictor::none);
  EXPECT_EQ(c.incompressibility.method, IncompressibilityMethod::penalty);
  EXPECT_EQ(c.newton.maximumIterations, 25);
  EXPECT_EQ(c.linear.tolerance, 1e-8);
  EXPECT_EQ(c.linear.mueLuSmoother, MueLuSmoother::chebyshev);
  EXPECT_EQ(c.output.volumeFaceSets, (std::vector<std::string>{"inner", "outer"}));
  EXPECT_TRUE(c.output.resultantFaceSets.empty());
  EXPECT_EQ(c.output.checkpointEvery, 0);
  EXPECT_EQ(c.output.directory, "results/run_configuration"); // named after the deck
  EXPECT_TRUE(c.controlled);
  EXPECT_FALSE(parseRunConfiguration(test::deckOnFile("run_uncontrolled.xml", "", schema())).controlled);
}

TEST(RunConfiguration, TheListingHasEveryParameterWithDoublesTo17Digits) {
  const std::string listing = configuration("run_listing.xml").listing;
  EXPECT_NE(listing.find("Time/end time = 2\n"), std::string::npos) << listing;
  EXPECT_NE(listing.find("Time/step size = 0.10000000000000001\n"), std::string::npos) << listing; // a default
  EXPECT_NE(listing.find("Output/volume face sets = inner , outer\n"), std::string::npos) << listing;
  EXPECT_NE(listing.find("Control/type = gradient\n"), std::string::npos) << listing;
  EXPECT_NE(listing.find("Nonlinear solver/"), std::string::npos) << listing;
}

TEST(RunConfiguration, IterativeOnlySettingsGivenAreListedWithWhereTheyWereGiven) {
  const RunConfiguration c = configuration("run_iterative.xml", {"Linear solver/coarse size=500"});
  // In the order the parameters are declared; "tolerance" serves a direct solve's refinement too.
  EXPECT_EQ(c.givenIterativeOnly,
            (std::vector<std::string>{
                "deck " + test::deckPath("run_iterative.xml") + ":11: parameter 'Linear solver/MueLu smoother'",
                "deck " + test::deckPath("run_iterative.xml") +
                    " (--set on the command line): parameter 'Linear solver/coarse size'"}));
  EXPECT_EQ(c.linear.coarseSize, 500);
  EXPECT_TRUE(parseRunConfiguration(test::deckOnFile("run_plain.xml", "", schema())).givenIterativeOnly.empty());
}

TEST(RunConfiguration, AnAirflowCoupledInTheUzawaLoopKeepsTheDirectFactorsForTheStep) {
  EXPECT_EQ(configuration("run_no_airflow.xml").linear.directReuseScope, ReuseScope::newtonSolve);
  EXPECT_EQ(configuration("run_airflow.xml", {"Airflow/driven by=pressures"}).linear.directReuseScope, ReuseScope::step);
  EXPECT_EQ(configuration("run_airflow_around.xml", {"Airflow/driven by=pressures", "Airflow/coupling loop=step solve"})
                .linear.directReuseScope,
            ReuseScope::newtonSolve);
  // A scope the deck gives stands.
  EXPECT_EQ(configuration("run_airflow_given.xml",
                          {"Airflow/driven by=pressures", "Linear solver/direct reuse scope=Newton solve"})
                .linear.directReuseScope,
            ReuseScope::newtonSolve);
}

TEST(RunConfiguration, TheFirstDifferenceOfTwoListings) {
  const std::string run = configuration("run_first.xml").listing;
  EXPECT_EQ(firstListingDifference(run, configuration("run_same.xml").listing), "");
  EXPECT_EQ(firstListingDifference(run, configuration("run_longer.xml", {"Time/end time=3"}).listing),
            "the run's Time/end time = 2, now Time/end time = 3");
  EXPECT_EQ(firstListingDifference("a = 1\n", "a = 1\nb = 2\n"), "the run's end, now b = 2");
  EXPECT_EQ(firstListingDifference("a = 1\nb = 2\n", "a = 1\n"), "the run's b = 2, now end");
}

TEST(RunConfiguration, ListingDifferencesReadAsTheDeckWroteThem) {
  // The listing keeps 17 digits (a restart compares exactly); its message, the shortest form.
  const std::string run = configuration("run_longer.xml", {"Time/end time=0.6"}).listing;
  EXPECT_EQ(firstListingDifference(run, configuration("run_longer.xml", {"Time/end time=0.7"}).listing),
            "the run's Time/end time = 0.6, now Time/end time = 0.7");
  EXPECT_EQ(firstListingDifference("g = {0.59999999999999998, -9.8100000000000005, 3}\n", "g = {0.6, -9.81, 4}\n"),
            "the run's g = {0.6, -9.81, 3}, now g = {0.6, -9.81, 4}");
  // Values that differ past the 16th digit still differ, and say so.
  EXPECT_EQ(firstListingDifference("x = 0.10000000000000001\n", "x = 0.10000000000000002\n"),
            "the run's x = 0.1, now x = 0.10000000000000002");
  // Names and short numbers stay as written.
  EXPECT_EQ(firstListingDifference("s8_1/cells = 1000000\n", "s8_1/cells = 2\n"),
            "the run's s8_1/cells = 1000000, now s8_1/cells = 2");
}

} // namespace
} // namespace glossa::solvers
