// The 1D airflow model on rigid channels against closed forms computed here independently of the
// section march: a uniform tube (Hagen-Poiseuille plus the entry's dynamic pressure), a converging
// channel and a converging-diverging one with no, partial and full pressure recovery past the
// throat; the flow each segment carries; prescribed pressures and flow rates round trip, also
// towards the nose; a closed section carries no flow; bad channels are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "airflow/AirflowModel.hpp"
#include "airflow/ChannelShapes.hpp"

namespace glossa::airflow {
namespace {

using test::kMu;
using test::kRho;
using test::positiveRoot;

AirSettings air(double recovery, double viscosity = kMu) { return {kRho, viscosity, recovery}; }

// 1/A^2 from 1/(2e-4)^2 at the nose to 1/(3e-5)^2 at s = 0.03 m and 1/(1.2e-4)^2 at 0.07 m: a
// throat of 30 mm^2 between wider ends, 15 sections 5 mm apart.
test::PeakedChannel peaked() { return {1.0 / (2e-4 * 2e-4), 1.0 / (3e-5 * 3e-5), 1.0 / (1.2e-4 * 1.2e-4), 0.03, 0.07, 15}; }

TEST(AirflowModel, UniformTubeIsHagenPoiseuilleWithTheEntryDynamicPressure) {
  const double R = 5e-3, A = M_PI * R * R, L = 0.08, pn = 0.0, pt = -50.0;
  Channel c(9);
  for (int i = 0; i < 9; ++i) c[i] = {L * i / 8.0, A};
  const FlowSolution s = AirflowModel(c, air(0.0)).withPressures(pn, pt);
  // dp = rho u^2 / 2 + 8 mu L Q / (pi R^4)
  const double poiseuille = 8.0 * kMu / (M_PI * std::pow(R, 4));
  const double Q = positiveRoot(0.5 * kRho / (A * A), poiseuille * L, pn - pt);
  EXPECT_NEAR(s.flowRate, Q, 1e-10 * Q);
  EXPECT_EQ(s.throat, 0);
  EXPECT_FALSE(s.choked);
  for (int i = 0; i < 9; ++i)
    EXPECT_NEAR(s.pressure[i], pn - 0.5 * kRho * Q * Q / (A * A) - poiseuille * Q * c[i].arcLength, 1e-10 * 50.0);
}

TEST(AirflowModel, ConvergingChannelMatchesBernoulliPlusPoiseuilleInClosedForm) {
  // 1/A^2 linear from 150 mm^2 at the nose to 40 mm^2 at the far end, the throat; the recovery
  // coefficient has nothing to act on.
  const double g0 = 1.0 / (1.5e-4 * 1.5e-4), g1 = 1.0 / (4e-5 * 4e-5), L = 0.06, dp = 120.0;
  const test::PeakedChannel shape{g0, g1, g1, L, L, 13};
  for (double recovery : {0.0, 0.3}) {
    const FlowSolution s = AirflowModel(shape.channel(), air(recovery)).withPressures(dp, 0.0);
    const double Q = positiveRoot(0.5 * kRho * g1, 8.0 * M_PI * kMu * 0.5 * (g0 + g1) * L, dp);
    EXPECT_NEAR(s.flowRate, Q, 1e-10 * Q) << "recovery " << recovery;
    EXPECT_EQ(s.throat, 12);
    EXPECT_NEAR(s.pressure.back(), 0.0, 1e-10 * dp);
  }
}

TEST(AirflowModel, ThroatWithRecoveryCoefficientMatchesTheClosedForm) {
  const test::PeakedChannel shape = peaked();
  const double pn = 30.0, pt = -170.0, dp = pn - pt;
  for (double cr : {0.0, 0.4, 1.0}) {
    const FlowSolution s = AirflowModel(shape.channel(), air(cr)).withPressures(pn, pt);
    // dp = rho Q^2/2 ((1 - c_r)/A_m^2 + c_r/A_N^2) + 8 pi mu Q integral(1/A^2)
    const double a = 0.5 * kRho * ((1.0 - cr) * shape.gThroat + cr * shape.gEnd);
    const double Q = positiveRoot(a, 8.0 * M_PI * kMu * shape.integralOfInverseSquareArea(), dp);
    EXPECT_NEAR(s.flowRate, Q, 1e-10 * Q) << "recovery " << cr;
    EXPECT_EQ(s.throat, 6);
  }
}

TEST(AirflowModel, NoRecoveryPastTheThroatKeepsTheThroatPressureDownstream) {
  // Inviscid, c_r = 0: the jet leaves the throat at p_m = p_n - rho u_m^2 / 2 and the pressure
  // stays there to the trachea, so u_m = sqrt(2 (p_n - p_t) / rho).
  const test::PeakedChannel shape = peaked();
  const double pn = 0.0, pt = -80.0;
  const FlowSolution s = AirflowModel(shape.channel(), air(0.0, 0.0)).withPressures(pn, pt);
  const double Am = 1.0 / std::sqrt(shape.gThroat);
  const double Q = Am * std::sqrt(2.0 * (pn - pt) / kRho);
  EXPECT_NEAR(s.flowRate, Q, 1e-10 * Q);
  for (int i = 6; i < shape.sections; ++i) EXPECT_NEAR(s.pressure[i], pt, 1e-10 * 80.0) << "section " << i;
  // Upstream of the throat Bernoulli holds: p_i + rho Q^2 / (2 A_i^2) = p_n.
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(s.pressure[i] + 0.5 * kRho * Q * Q * shape.inverseSquareArea(i * 0.005), pn, 1e-10 * 80.0);
}

TEST(AirflowModel, EverySegmentCarriesTheSameFlowRate) {
  // Mass conservation: the flow rate each segment's own pressure difference drives (its
  // Bernoulli + Poiseuille relation inverted here) is the solved Q everywhere, so rho Q is too.
  const test::PeakedChannel shape = peaked();
  const Channel c = shape.channel();
  const FlowSolution s = AirflowModel(c, air(0.0)).withPressures(10.0, -150.0);
  const double Q = s.flowRate;
  const double entry = std::sqrt(2.0 * (10.0 - s.pressure[0]) / (kRho * shape.gStart));
  EXPECT_NEAR(entry, Q, 1e-10 * Q);
  for (int j = 0; j + 1 < shape.sections; ++j) {
    const double g0 = 1.0 / (c[j].area * c[j].area), g1 = 1.0 / (c[j + 1].area * c[j + 1].area);
    const double b = 4.0 * M_PI * kMu * (c[j + 1].arcLength - c[j].arcLength) * (g0 + g1);
    const double drop = s.pressure[j] - s.pressure[j + 1];
    const double q = j < 6 ? positiveRoot(0.5 * kRho * (g1 - g0), b, drop) : drop / b;
    EXPECT_NEAR(q, Q, 1e-9 * Q) << "segment " << j;
  }
}

TEST(AirflowModel, PrescribedPressuresAndFlowRateRoundTrip) {
  const AirflowModel model(peaked().channel(), air(0.25));
  const FlowSolution driven = model.withPressures(20.0, -300.0);
  const FlowSolution back = model.withFlowRate(20.0, driven.flowRate);
  EXPECT_NEAR(back.trachealPressure, -300.0, 1e-10 * 320.0);
  for (std::size_t i = 0; i < back.pressure.size(); ++i) EXPECT_NEAR(back.pressure[i], driven.pressure[i], 1e-10 * 320.0);
  const double Q = 2.5e-4;
  const FlowSolution prescribed = model.withFlowRate(-5.0, Q);
  EXPECT_NEAR(model.withPressures(-5.0, prescribed.trachealPressure).flowRate, Q, 1e-10 * Q);
}

TEST(AirflowModel, ExpirationIsTheMirroredChannelDrivenFromTheTrachea) {
  const Channel c = peaked().channel();
  Channel mirrored(c.rbegin(), c.rend());
  for (auto &s : mirrored) s.arcLength = c.back().arcLength - s.arcLength;
  const AirflowModel model(c, air(0.25)), mirror(mirrored, air(0.25));
  const FlowSolution out = model.withPressures(-40.0, 160.0), in = mirror.withPressures(160.0, -40.0);
  EXPECT_LT(out.flowRate, 0.0);
  EXPECT_NEAR(-out.flowRate, in.flowRate, 1e-12 * in.flowRate);
  EXPECT_EQ(out.throat, 6);
  const int n = static_cast<int>(c.size());
  for (int i = 0; i < n; ++i) EXPECT_NEAR(out.pressure[i], in.pressure[n - 1 - i], 1e-10 * 200.0);
  // And back: the nasal pressure and that flow rate give the tracheal pressure.
  const FlowSolution back = model.withFlowRate(-40.0, out.flowRate);
  EXPECT_NEAR(back.trachealPressure, 160.0, 1e-10 * 200.0);
  EXPECT_NEAR(back.nasalPressure, -40.0, 0.0);
}

TEST(AirflowModel, EqualEndPressuresDriveNoFlow) {
  const FlowSolution s = AirflowModel(peaked().channel(), air(0.0)).withPressures(-12.0, -12.0);
  EXPECT_EQ(s.flowRate, 0.0);
  for (double p : s.pressure) EXPECT_EQ(p, -12.0);
}

TEST(AirflowModel, AClosedSectionCarriesNoFlow) {
  for (bool byArea : {true, false}) {
    Channel c = peaked().channel();
    if (byArea) c[5].area = 0.0;
    c[5].closed = !byArea;
    c[8].closed = true;  // a second closure: the pocket between the two is at the mean
    const AirflowModel model(c, air(0.0));
    const FlowSolution s = model.withPressures(0.0, -400.0);
    EXPECT_EQ(s.flowRate, 0.0);
    EXPECT_TRUE(s.closed);
    EXPECT_EQ(s.firstClosed, 5);
    EXPECT_EQ(s.lastClosed, 8);
    for (int i = 0; i < 15; ++i) EXPECT_EQ(s.pressure[i], i < 5 ? 0.0 : i > 8 ? -400.0 : -200.0) << "section " << i;
    EXPECT_THROW(model.withFlowRate(0.0, 1e-4), std::domain_error);
    const FlowSolution still = model.withFlowRate(3.0, 0.0);
    for (double p : still.pressure) EXPECT_EQ(p, 3.0);
  }
}

TEST(AirflowModel, BadChannelsAndConstantsAreRefused) {
  const Channel good = peaked().channel();
  auto refused = [](Channel c, AirSettings a) {
    EXPECT_THROW(AirflowModel(std::move(c), a), std::invalid_argument);
  };
  refused(Channel(good.begin(), good.begin() + 1), air(0.0));
  Channel c = good;
  c[3].arcLength = c[2].arcLength;
  refused(c, air(0.0));
  c = good;
  c[3].area = NAN;  // an unmeasured section
  refused(c, air(0.0));
  c = good;
  c[3].area = -1e-6;
  refused(c, air(0.0));
  c = good;
  c[3].compliance = -1e-9;
  refused(c, air(0.0));
  refused(good, air(1.5));
  refused(good, air(0.0, -1e-5));
  refused(good, AirSettings{0.0, kMu, 0.0});
  EXPECT_THROW(AirflowModel(good, air(0.0)).withPressures(NAN, 0.0), std::invalid_argument);
  EXPECT_THROW(AirflowModel(good, air(0.0)).withFlowRate(0.0, INFINITY), std::invalid_argument);
}

}  // namespace
}  // namespace glossa::airflow
