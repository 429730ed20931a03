// The 3D ironing problem with a rigid die (inputs/verification/ironing_rigid_die.xml, doc/contact.md):
// a cylinder pressed 1 into a neo-Hookean slab and slid 4 along it, with Coulomb friction
// mu = 0.3 and without. Both run through with no step cut below the deck's minimum step size
// (a cut below it fails the run). With friction, every contact point slides once the die moves:
// the friction force is mu times the normal force (Coulomb's law, the independent reference) to
// 2 % at every step from half a unit of sliding on. Without friction, no tangential force. The
// normal force history is smooth: while the die slides, no step changes it by more than 5 %.
#include <cmath>

#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {

const double mu = 0.3;

std::vector<test::KeyedRow> ironing(double coefficient, const std::string &name) {
  const auto output = test::scratchDirectory(name);
  const auto s = test::runDeck(test::inputPath("verification/ironing_rigid_die.xml"),
                               {"Contact/die/friction coefficient=" + std::to_string(coefficient)}, output);
  EXPECT_TRUE(s.at("converged").get<bool>()) << name;
  EXPECT_TRUE(s.at("contact").at("gap_tolerance_met").get<bool>()) << name;
  const auto rows = test::readKeyedCsv(output / "contact.csv").at("die");
  EXPECT_EQ(rows.back().time, 3.0) << name;
  return rows;
}

// Columns of contact.csv after the time and the contact's name.
constexpr std::size_t kNormal = 1, kTangential = 5;

void expectSmoothWhileSliding(const std::vector<test::KeyedRow> &rows, const std::string &name) {
  for (std::size_t k = 1; k < rows.size(); ++k) {
    if (rows[k - 1].time < 1.0 + 1e-9) continue;
    const double before = rows[k - 1].values[kNormal], after = rows[k].values[kNormal];
    EXPECT_LT(std::abs(after - before), 0.05 * before) << name << " t = " << rows[k].time;
  }
}

} // namespace

TEST(Ironing, WithFrictionTheTangentialForceIsMuTimesTheNormalWhileSliding) {
  const auto rows = ironing(mu, "ironing_friction");
  int sliding = 0;
  for (const auto &r : rows) {
    if (r.time < 1.0 + 0.5 / 2.0 - 1e-9) continue;  // the die slides 2 per unit time
    const double N = r.values[kNormal], T = r.values[kTangential];
    ASSERT_GT(N, 0.0) << "t = " << r.time;
    EXPECT_NEAR(T / N, mu, 0.02 * mu) << "t = " << r.time;
    ++sliding;
  }
  EXPECT_GE(sliding, 10);
  expectSmoothWhileSliding(rows, "friction");
}

TEST(Ironing, WithoutFrictionRunsThroughWithNoTangentialForce) {
  const auto rows = ironing(0.0, "ironing_frictionless");
  for (const auto &r : rows) EXPECT_EQ(r.values[kTangential], 0.0) << "t = " << r.time;
  expectSmoothWhileSliding(rows, "frictionless");
}
