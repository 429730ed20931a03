// The Airflow section parsed into its struct: off by default; driven by pressures or by a flow
// rate, each a value times its time function; and each deck it refuses (a parameter the drive
// does not read, a value out of its range) with the file, line, parameter and what is allowed.
#include <gtest/gtest.h>

#include "DeckOnFile.hpp"
#include "input/AirflowParameters.hpp"

namespace glossa::input {
namespace {

Teuchos::ParameterList schema() {
  Teuchos::ParameterList s("Glossa");
  s.set("Airflow", airflowParameters());
  return s;
}

AirflowParameters parsed(const std::string &name, const std::string &airflow, double endTime = 2.0) {
  return parseAirflowParameters(test::deckOnFile(name, airflow, schema()), endTime);
}

std::string refusal(const std::string &name, const std::string &airflow) {
  try {
    const io::Deck deck = test::deckOnFile(name, airflow, schema());
    return test::deckErrorOf([&] { parseAirflowParameters(deck, 2.0); });
  } catch (const io::DeckError &e) {  // refused by the validation against the schema
    return e.what();
  }
}

TEST(AirflowParameters, OffByDefaultWithTheAirOfTheBrief) {
  const AirflowParameters p = parsed("airflow_defaults.xml", "");
  EXPECT_EQ(p.drive, AirflowDrive::off);
  const AirflowParameters on = parsed("airflow_on.xml", R"X(<ParameterList name="Airflow">
  <Parameter name="driven by" type="string" value="pressures"/>
</ParameterList>
)X");
  EXPECT_EQ(on.drive, AirflowDrive::pressures);
  EXPECT_EQ(on.density, 1.2);
  EXPECT_EQ(on.viscosity, 1.8e-5);
  EXPECT_EQ(on.recoveryCoefficient, 0.0);
  EXPECT_EQ(on.mapping, AirflowMapping::linear);
  EXPECT_EQ(on.couplingTolerance, 0.1);
  EXPECT_EQ(on.relaxation, 0.5);
  EXPECT_EQ(on.maximumCouplingIterations, 30);
  EXPECT_EQ(on.loop, AirflowLoop::uzawaLoop);
  EXPECT_EQ(on.couplingMethod, airflow::CouplingMethod::aitken);
  EXPECT_EQ(on.nasalPressure(0.7), 0.0);
  EXPECT_EQ(on.trachealPressure(0.7), 0.0);
}

TEST(AirflowParameters, PressuresAsValuesTimesTheirTimeFunctions) {
  const AirflowParameters p = parsed("airflow_pressures.xml", R"X(<ParameterList name="Airflow">
  <Parameter name="driven by" type="string" value="pressures"/>
  <Parameter name="nasal pressure" type="double" value="5"/>
  <Parameter name="tracheal pressure" type="double" value="-800"/>
  <ParameterList name="tracheal pressure time function">
    <Parameter name="type" type="string" value="table"/>
    <Parameter name="times" type="Array(double)" value="{0, 1, 2}"/>
    <Parameter name="values" type="Array(double)" value="{0, 1, 0}"/>
  </ParameterList>
  <Parameter name="air density" type="double" value="1.15"/>
  <Parameter name="air viscosity" type="double" value="1.9e-5"/>
  <Parameter name="recovery coefficient" type="double" value="0.3"/>
  <Parameter name="pressure mapping" type="string" value="nearest section"/>
  <Parameter name="coupling tolerance" type="double" value="0.02"/>
  <Parameter name="relaxation" type="double" value="1"/>
  <Parameter name="maximum coupling iterations" type="int" value="12"/>
  <Parameter name="coupling loop" type="string" value="step solve"/>
  <Parameter name="coupling method" type="string" value="quasi-Newton"/>
</ParameterList>
)X");
  EXPECT_EQ(p.drive, AirflowDrive::pressures);
  EXPECT_EQ(p.loop, AirflowLoop::stepSolve);
  EXPECT_EQ(p.couplingMethod, airflow::CouplingMethod::quasiNewton);
  EXPECT_EQ(p.nasalPressure(1.3), 5.0);
  EXPECT_DOUBLE_EQ(p.trachealPressure(0.25), -200.0);
  EXPECT_DOUBLE_EQ(p.trachealPressure(1.5), -400.0);
  EXPECT_EQ(p.density, 1.15);
  EXPECT_EQ(p.viscosity, 1.9e-5);
  EXPECT_EQ(p.recoveryCoefficient, 0.3);
  EXPECT_EQ(p.mapping, AirflowMapping::nearestSection);
  EXPECT_EQ(p.couplingTolerance, 0.02);
  EXPECT_EQ(p.relaxation, 1.0);
  EXPECT_EQ(p.maximumCouplingIterations, 12);
}

TEST(AirflowParameters, AFlowRateAsABreath) {
  const AirflowParameters p = parsed("airflow_flow_rate.xml", R"X(<ParameterList name="Airflow">
  <Parameter name="driven by" type="string" value="flow rate"/>
  <Parameter name="flow rate" type="double" value="5e-4"/>
  <ParameterList name="flow rate time function">
    <Parameter name="type" type="string" value="ramp"/>
  </ParameterList>
</ParameterList>
)X");
  EXPECT_EQ(p.drive, AirflowDrive::flowRate);
  // A ramp without a duration spans the deck's end time, 2 s here.
  EXPECT_DOUBLE_EQ(p.flowRate(0.5), 1.25e-4);
  EXPECT_EQ(p.nasalPressure(0.5), 0.0);
}

TEST(AirflowParameters, WhatTheDriveDoesNotReadIsRefused) {
  const std::string at = "deck " + test::deckPath("airflow_unread.xml");
  EXPECT_EQ(refusal("airflow_unread.xml", R"X(<ParameterList name="Airflow">
  <Parameter name="driven by" type="string" value="flow rate"/>
  <Parameter name="tracheal pressure" type="double" value="-800"/>
</ParameterList>
)X"),
            at + ":4: parameter 'Airflow/tracheal pressure' is not read when 'driven by' is flow rate (only with "
                 "pressures), so its value would be ignored; remove it or change 'driven by'");
  EXPECT_EQ(refusal("airflow_unread.xml", R"X(<ParameterList name="Airflow">
  <Parameter name="air density" type="double" value="1.1"/>
</ParameterList>
)X"),
            at + ":3: parameter 'Airflow/air density' is not read when 'driven by' is off (only with pressures, "
                 "flow rate), so its value would be ignored; remove it or change 'driven by'");
  const std::string sublist = refusal("airflow_unread.xml", R"X(<ParameterList name="Airflow">
  <Parameter name="driven by" type="string" value="pressures"/>
  <ParameterList name="flow rate time function">
    <Parameter name="type" type="string" value="ramp"/>
  </ParameterList>
</ParameterList>
)X");
  EXPECT_EQ(sublist.rfind(at + ":4: parameter 'Airflow/flow rate time function' is not read", 0), 0u) << sublist;
}

TEST(AirflowParameters, ValuesOutOfRangeAreRefusedWithTheRange) {
  const std::string recovery = refusal("airflow_range.xml", R"X(<ParameterList name="Airflow">
  <Parameter name="driven by" type="string" value="pressures"/>
  <Parameter name="recovery coefficient" type="double" value="1.5"/>
</ParameterList>
)X");
  EXPECT_NE(recovery.find(test::deckPath("airflow_range.xml") + ":4"), std::string::npos) << recovery;
  EXPECT_NE(recovery.find("Airflow/recovery coefficient"), std::string::npos) << recovery;
  EXPECT_NE(recovery.find("0 <= value <= 1"), std::string::npos) << recovery;
  const std::string density = refusal("airflow_range.xml", R"X(<ParameterList name="Airflow">
  <Parameter name="driven by" type="string" value="pressures"/>
  <Parameter name="air density" type="double" value="0"/>
</ParameterList>
)X");
  EXPECT_NE(density.find("Airflow/air density"), std::string::npos) << density;
  EXPECT_NE(density.find("value > 0"), std::string::npos) << density;
  const std::string drive = refusal("airflow_range.xml", R"X(<ParameterList name="Airflow">
  <Parameter name="driven by" type="string" value="volume"/>
</ParameterList>
)X");
  EXPECT_NE(drive.find("Airflow/driven by"), std::string::npos) << drive;
  EXPECT_NE(drive.find("flow rate"), std::string::npos) << drive;
}

}  // namespace
}  // namespace glossa::input
