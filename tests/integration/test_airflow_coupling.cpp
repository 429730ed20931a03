// The airflow coupled to the solid (doc/airflow.md, "Coupling"), on the collapsible channel of
// inputs/verification/airflow_collapsible_channel.xml: air flows between a soft block and a rigid
// roof that narrows to a throat, from 0 Pa at the nasal end to a tracheal pressure lowered to
// -150 Pa. What each test checks against:
//  - both models at once: the pressures the solid was solved with (airflow.csv) are those the 1D
//    flow gives through the lumen it then has (airway.csv's areas, put through AirflowModel here
//    afresh), to the coupling tolerance, and the solid's step converged;
//  - flow limitation: the rigid channel (the areas at rest) keeps gaining flow as the tracheal
//    pressure falls, as the square root of the drop; the collapsible one stops gaining;
//  - the four coupling methods reach the same flow, Newton's with the solid's Jacobian in the
//    fewest iterations, then the quasi-Newton one, and constant relaxation in the most; coupled
//    around whole step solves or inside the Uzawa loop, the same flow.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "CsvRows.hpp"
#include "RunDeck.hpp"
#include "airflow/AirflowModel.hpp"

using namespace glossa;

namespace {
constexpr int kSections = 10;
constexpr double kTolerance = 0.01; // the deck's coupling tolerance [Pa]

std::string two(int k) { return (k < 10 ? "0" : "") + std::to_string(k); }

struct ChannelRun {
  nlohmann::json summary;
  std::vector<std::map<std::string, double>> airflow, airway;
  std::vector<double> arcLengths; // of the sections (airway_sections.csv)
};

// Each test its own `tag`: ctest runs the tests of this file side by side.
ChannelRun runChannel(const std::string &tag, const std::vector<std::string> &overrides = {}) {
  const auto dir = test::scratchDirectory("airflow_collapsible_" + tag);
  ChannelRun run;
  run.summary = test::runDeck(test::inputPath("verification/airflow_collapsible_channel.xml"), overrides, dir);
  run.airflow = test::readCsvRows(dir / "airflow.csv");
  run.airway = test::readCsvRows(dir / "airway.csv");
  for (const auto &r : test::readCsvRows(dir / "airway_sections.csv")) run.arcLengths.push_back(r.at("arc_length"));
  return run;
}

// The flow through the channel of a recorded lumen (every section measured on this channel), as
// the coupling's own flow model computes it, from airway.csv's row.
airflow::FlowSolution flowThrough(const std::map<std::string, double> &lumen, double trachealPressure,
                                  const std::vector<double> &arcLengths) {
  airflow::Channel channel;
  for (int k = 0; k < kSections; ++k)
    channel.push_back({arcLengths[static_cast<std::size_t>(k)], lumen.at("area_" + two(k)), 0.0, false});
  return airflow::AirflowModel(channel, airflow::AirSettings{}).withPressures(0.0, trachealPressure);
}
} // namespace

TEST(AirflowCoupling, CollapsibleChannelSatisfiesTheFlowAndTheSolidEveryStep) {
  const ChannelRun run = runChannel("both_models");
  ASSERT_TRUE(run.summary.at("converged").get<bool>());
  ASSERT_EQ(run.airflow.size(), 11u); // t = 0 and 10 steps
  ASSERT_EQ(run.airway.size(), run.airflow.size());
  const std::vector<double> &s = run.arcLengths;
  ASSERT_EQ(s.size(), static_cast<std::size_t>(kSections));
  for (std::size_t i = 1; i < run.airflow.size(); ++i) {
    const auto &row = run.airflow[i];
    SCOPED_TRACE("t = " + std::to_string(row.at("time")));
    EXPECT_EQ(run.airway[i].at("time"), row.at("time"));
    // Coupled, not one pass: the flow moved the wall, which moved the flow.
    EXPECT_GE(row.at("coupling_iterations"), 2.0);
    EXPECT_LE(row.at("coupling_change"), kTolerance);
    const airflow::FlowSolution flow = flowThrough(run.airway[i], row.at("tracheal_pressure"), s);
    EXPECT_FALSE(flow.closed);
    for (int k = 0; k < kSections; ++k)
      EXPECT_NEAR(row.at("pressure_" + two(k)), flow.pressure[static_cast<std::size_t>(k)], kTolerance) << k;
    // The flow rate of the last measured lumen is the one reported.
    EXPECT_NEAR(row.at("flow_rate"), flow.flowRate, 1e-12 * flow.flowRate);
    EXPECT_EQ(row.at("smallest_area"), run.airway[i].at("smallest_area"));
  }
}

TEST(AirflowCoupling, CollapsibleChannelLimitsTheFlowWhereTheRigidOneKeepsGaining) {
  const ChannelRun run = runChannel("limitation");
  ASSERT_TRUE(run.summary.at("converged").get<bool>());
  const std::vector<double> &s = run.arcLengths;
  const auto &atRest = run.airway.front();
  const std::size_t n = run.airflow.size();
  const double pLast = run.airflow[n - 1].at("tracheal_pressure"), pBefore = run.airflow[n - 3].at("tracheal_pressure");
  ASSERT_NEAR(pLast, -150.0, 1e-9);
  // Over the last 30 Pa of the drop: the rigid channel (inviscid, Q ~ sqrt(drop)) gains about
  // 10 %, the collapsible one almost nothing, and carries far less.
  const double rigidLast = flowThrough(atRest, pLast, s).flowRate, rigidBefore = flowThrough(atRest, pBefore, s).flowRate;
  const double qLast = run.airflow[n - 1].at("flow_rate"), qBefore = run.airflow[n - 3].at("flow_rate");
  EXPECT_GT((rigidLast - rigidBefore) / rigidLast, 0.08);
  EXPECT_LT(std::abs(qLast - qBefore) / qLast, 0.01);
  EXPECT_LT(qLast, 0.7 * rigidLast);
  // Rising at first: the first 15 Pa bring the flow to under half of what it ends at.
  EXPECT_LT(run.airflow[1].at("flow_rate"), 0.5 * qLast);
  // The throat narrows as the suction grows.
  for (std::size_t i = 1; i < n; ++i) EXPECT_LT(run.airflow[i].at("smallest_area"), run.airflow[i - 1].at("smallest_area"));
}

TEST(AirflowCoupling, TheFourMethodsAgreeNewtonsInTheFewestIterations) {
  std::map<std::string, double> flow, iterations;
  for (const std::string method : {"constant relaxation", "Aitken", "quasi-Newton", "Newton"}) {
    const ChannelRun run = runChannel(method.substr(0, method.find(' ')),
                                      {"Airflow/coupling method=" + method, "Airflow/coupling tolerance=1e-6",
                                       "Airflow/maximum coupling iterations=200"});
    ASSERT_TRUE(run.summary.at("converged").get<bool>()) << method;
    flow[method] = run.airflow.back().at("flow_rate");
    for (const auto &row : run.airflow) iterations[method] += row.at("coupling_iterations");
    EXPECT_EQ(run.summary.at("airflow").at("coupling_iterations").get<double>(), iterations[method]) << method;
  }
  EXPECT_NEAR(flow["Aitken"], flow["constant relaxation"], 1e-6 * flow["Aitken"]);
  EXPECT_NEAR(flow["quasi-Newton"], flow["constant relaxation"], 1e-6 * flow["Aitken"]);
  EXPECT_NEAR(flow["Newton"], flow["constant relaxation"], 1e-6 * flow["Aitken"]);
  EXPECT_LT(iterations["Newton"], iterations["quasi-Newton"]);
  EXPECT_LT(iterations["quasi-Newton"], iterations["Aitken"]);
  EXPECT_LT(iterations["Aitken"], iterations["constant relaxation"]);
  const ChannelRun around = runChannel("around", {"Airflow/coupling loop=step solve", "Airflow/coupling tolerance=1e-6"});
  ASSERT_TRUE(around.summary.at("converged").get<bool>());
  EXPECT_NEAR(around.airflow.back().at("flow_rate"), flow["Aitken"], 1e-6 * flow["Aitken"]);
}
