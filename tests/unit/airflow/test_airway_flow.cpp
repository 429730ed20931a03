// The flow through a measured lumen (airflow/AirwayFlow): the lumen's measured sections are the
// flow model's channel, exactly; a section the lumen could not measure takes the pressure of its
// measured neighbours, linearly in arc length; a face's Gauss point takes the pressure at its arc
// length along the centreline. References: AirflowModel on the same channel, and interpolation by
// hand.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "airflow/AirwayFlow.hpp"

namespace glossa::airflow {
namespace {

constexpr int kSections = 5;
constexpr double kSpacing = 0.01;  // [m], sections along x at 0, 10, ... 40 mm
const double kAreas[kSections] = {2e-4, 1.5e-4, 5e-5, 1e-4, 1.2e-4};

airway::Centreline straightCentreline() {
  airway::Centreline c;
  for (int k = 0; k < kSections; ++k) {
    airway::SectionPlane plane;
    plane.origin = Eigen::Vector3d(kSpacing * k, 0.0, 0.003);
    c.planes.push_back(plane);
    c.arcLength.push_back(kSpacing * k);
  }
  return c;
}

airway::LumenState lumen(std::vector<bool> measured = std::vector<bool>(kSections, true)) {
  airway::LumenState s;
  for (int k = 0; k < kSections; ++k) {
    airway::SectionState section;
    section.measured = measured[static_cast<std::size_t>(k)];
    section.lumen.area = kAreas[k];
    s.sections.push_back(section);
  }
  s.smallest = 2;
  return s;
}

// One face whose four Gauss points sit at x = `x[q]` on the centreline's line.
std::vector<std::array<Eigen::Vector3d, 4>> gaussPointsAt(const std::array<double, 4> &x) {
  std::array<Eigen::Vector3d, 4> face;
  for (int q = 0; q < 4; ++q) face[static_cast<std::size_t>(q)] = Eigen::Vector3d(x[static_cast<std::size_t>(q)], 0.004, 0.0);
  return {face};
}

FlowDrive pressures(double tracheal) {
  FlowDrive d;
  d.trachealPressure = tracheal;
  return d;
}

TEST(AirwayFlow, TheMeasuredSectionsAreTheFlowModelsChannel) {
  const AirSettings air{1.2, 1.8e-5, 0.3};
  const AirwayFlow flow(straightCentreline(), {}, air, PressureMapping::linear);
  const AirwayFlowState s = flow.solve(lumen(), pressures(-200.0));
  Channel channel;
  for (int k = 0; k < kSections; ++k) channel.push_back({kSpacing * k, kAreas[k], 0.0, false});
  const FlowSolution direct = AirflowModel(channel, air).withPressures(0.0, -200.0);
  EXPECT_EQ(s.flow.flowRate, direct.flowRate);
  ASSERT_EQ(s.sectionPressure.size(), static_cast<std::size_t>(kSections));
  for (int k = 0; k < kSections; ++k) EXPECT_EQ(s.sectionPressure[static_cast<std::size_t>(k)], direct.pressure[static_cast<std::size_t>(k)]);
  EXPECT_EQ(s.smallest, 2);
  EXPECT_EQ(s.smallestArea, kAreas[2]);
}

TEST(AirwayFlow, AnUnmeasuredSectionTakesItsNeighboursPressureByArcLength) {
  const AirSettings air;
  const AirwayFlow flow(straightCentreline(), {}, air, PressureMapping::linear);
  const AirwayFlowState s = flow.solve(lumen({false, true, false, true, true}), pressures(-150.0));
  ASSERT_EQ(s.channelSections, (std::vector<int>{1, 3, 4}));
  const FlowSolution direct = AirflowModel({{kSpacing, kAreas[1], 0.0, false},
                                            {3 * kSpacing, kAreas[3], 0.0, false},
                                            {4 * kSpacing, kAreas[4], 0.0, false}},
                                           air)
                                  .withPressures(0.0, -150.0);
  EXPECT_EQ(s.flow.flowRate, direct.flowRate);
  EXPECT_EQ(s.sectionPressure[0], direct.pressure[0]);  // before the first measured: its pressure
  EXPECT_EQ(s.sectionPressure[1], direct.pressure[0]);
  EXPECT_NEAR(s.sectionPressure[2], 0.5 * (direct.pressure[0] + direct.pressure[1]), 1e-12);
  EXPECT_EQ(s.sectionPressure[4], direct.pressure[2]);
}

TEST(AirwayFlow, AFaceTakesThePressureAtItsArcLength) {
  const std::vector<double> p{-10.0, -30.0, -90.0, -95.0, -100.0};
  const auto points = gaussPointsAt({0.005, 0.0325, -0.01, 0.07});
  const auto linear = AirwayFlow(straightCentreline(), points, {}, PressureMapping::linear).facePressures(p);
  ASSERT_EQ(linear.size(), 1u);
  EXPECT_NEAR(linear[0][0], -20.0, 1e-12);                     // halfway between sections 0 and 1
  EXPECT_NEAR(linear[0][1], -95.0 + 0.25 * (-100.0 + 95.0), 1e-12);  // a quarter past section 3
  EXPECT_EQ(linear[0][2], -10.0);                              // before the first section
  EXPECT_EQ(linear[0][3], -100.0);                             // past the last
  const auto nearest = AirwayFlow(straightCentreline(), points, {}, PressureMapping::nearestSection).facePressures(p);
  EXPECT_EQ(nearest[0][1], -95.0);
}

TEST(AirwayFlow, AClosedSectionStopsTheFlowAndTooFewSectionsAreRefused) {
  const AirwayFlow flow(straightCentreline(), {}, {}, PressureMapping::linear);
  airway::LumenState shut = lumen();
  shut.sections[2].closed = true;
  const AirwayFlowState s = flow.solve(shut, pressures(-300.0));
  EXPECT_TRUE(s.flow.closed);
  EXPECT_EQ(s.flow.flowRate, 0.0);
  EXPECT_EQ(s.sectionPressure[0], 0.0);
  EXPECT_EQ(s.sectionPressure[4], -300.0);
  EXPECT_THROW(flow.solve(lumen({false, false, true, false, false}), pressures(-100.0)), std::invalid_argument);
}

}  // namespace
}  // namespace glossa::airflow
