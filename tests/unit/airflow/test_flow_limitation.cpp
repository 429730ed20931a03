// Flow limitation: the rigid channel's flow rate keeps rising with the pressure drop (as its
// square root when inviscid), while a compliant wall holds it at the wave-speed limit
// A sqrt(A / (rho dA/dp)) of the section where that limit is smallest, whatever the tracheal
// pressure below the onset; below the limit the compliant channel flows as the rigid one.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "airflow/AirflowModel.hpp"
#include "airflow/ChannelShapes.hpp"

namespace glossa::airflow {
namespace {

using test::kMu;
using test::kRho;

test::PeakedChannel shape() { return {1.0 / (2e-4 * 2e-4), 1.0 / (3e-5 * 3e-5), 1.0 / (1.2e-4 * 1.2e-4), 0.03, 0.07, 15}; }

TEST(FlowLimitation, TheRigidChannelDoesNotPlateau) {
  const AirflowModel inviscid(shape().channel(), {kRho, 0.0, 0.0});
  const double q1 = inviscid.withPressures(0.0, -100.0).flowRate, q4 = inviscid.withPressures(0.0, -400.0).flowRate;
  EXPECT_NEAR(q4 / q1, 2.0, 1e-12);
  const AirflowModel viscous(shape().channel(), {kRho, kMu, 0.0});
  EXPECT_EQ(viscous.waveSpeedLimit(), INFINITY);
  double previous = 0.0;
  for (double pt = -10.0; pt >= -5000.0; pt *= 1.5) {
    const FlowSolution s = viscous.withPressures(0.0, pt);
    EXPECT_FALSE(s.choked);
    EXPECT_GT(s.flowRate, previous * 1.1) << "tracheal pressure " << pt;
    previous = s.flowRate;
  }
}

TEST(FlowLimitation, ACompliantThroatChokesAtTheWaveSpeedLimit) {
  Channel rigid = shape().channel(), compliant = rigid;
  // The throat (30 mm^2) with dA/dp = 2e-8 m^2/Pa, a wider section with a larger limit.
  compliant[6].compliance = 2e-8;
  compliant[2].compliance = 2e-8;
  const AirflowModel model(compliant, {kRho, kMu, 0.0}), rigidModel(rigid, {kRho, kMu, 0.0});
  const double A = rigid[6].area, limit = A * std::sqrt(A / (kRho * 2e-8));
  int section = -1;
  EXPECT_NEAR(model.waveSpeedLimit(&section), limit, 1e-14 * limit);
  EXPECT_EQ(section, 6);
  // The onset: the tracheal pressure at which the rigid channel carries the limit.
  const double onset = rigidModel.withFlowRate(0.0, limit).trachealPressure;
  ASSERT_LT(onset, 0.0);
  for (double factor : {0.2, 0.5, 0.9, 0.999}) {
    const FlowSolution s = model.withPressures(0.0, factor * onset), r = rigidModel.withPressures(0.0, factor * onset);
    EXPECT_FALSE(s.choked) << factor;
    EXPECT_NEAR(s.flowRate, r.flowRate, 1e-12 * r.flowRate) << factor;
  }
  for (double factor : {1.001, 1.5, 3.0, 10.0}) {
    const FlowSolution s = model.withPressures(0.0, factor * onset);
    EXPECT_TRUE(s.choked) << factor;
    EXPECT_EQ(s.chokeSection, 6);
    EXPECT_EQ(s.flowRate, limit) << factor;  // the plateau
    // The sections carry the march at the limit, down to the onset's pressure; the rest is past the choke.
    EXPECT_NEAR(s.pressure.back(), onset, 1e-10 * std::abs(onset));
    EXPECT_NEAR(s.chokeDrop, onset - factor * onset, 1e-10 * std::abs(factor * onset));
  }
  EXPECT_THROW(model.withFlowRate(0.0, 1.01 * limit), std::domain_error);
  EXPECT_THROW(model.withFlowRate(0.0, -1.01 * limit), std::domain_error);
}

}  // namespace
}  // namespace glossa::airflow
