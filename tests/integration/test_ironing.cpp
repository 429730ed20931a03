// The 3D ironing problem of Puso and Laursen (inputs/verification/ironing_rigid_die.xml,
// doc/contact.md): a rigid cylindrical die pressed 1.4 into a neo-Hookean slab and slid 4 along
// it, with Coulomb friction mu = 0.3 and without. Both run through with no step cut below the
// deck's minimum step size (a cut below it fails the run). No published reaction force was
// found to compare with (doc/contact.md says what was searched), so the references are
// independent laws:
// - Coulomb's: once the slab has stopped following the die (from two units of sliding on), the
//   friction force is mu times the normal force, to 2 %;
// - mirror symmetry: without friction the state depends only on where the die is, and its start
//   and end (x = 2.5 and 6.5) are mirror images about the slab's middle (x = 4.5), so the normal
//   force at die position 2.5 + s equals that at 6.5 - s and the horizontal force changes sign.
// The histories are smooth: while the die slides, no step changes the normal force by more than
// 5 % (measured: under 3 %).
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {

const double mu = 0.3;

struct Histories {
  std::vector<test::KeyedRow> contact, top;
};

Histories ironing(double coefficient, const std::string &name) {
  const auto output = test::scratchDirectory(name);
  const auto s = test::runDeck(test::inputPath("verification/ironing_rigid_die.xml"),
                               {"Contact/die/friction coefficient=" + std::to_string(coefficient)}, output);
  EXPECT_TRUE(s.at("converged").get<bool>()) << name;
  EXPECT_TRUE(s.at("contact").at("gap_tolerance_met").get<bool>()) << name;
  Histories h{test::readKeyedCsv(output / "contact.csv").at("die"),
              test::readKeyedCsv(output / "resultants.csv").at("zmax")};
  EXPECT_EQ(h.contact.back().time, 3.0) << name;
  return h;
}

// Columns of contact.csv after the time and the contact's name; of resultants.csv, fx.
constexpr std::size_t kNormal = 1, kTangential = 5, kFx = 0;

void expectSmoothWhileSliding(const std::vector<test::KeyedRow> &rows, const std::string &name) {
  for (std::size_t k = 1; k < rows.size(); ++k) {
    if (rows[k - 1].time < 1.0 + 1e-9) continue;
    const double before = rows[k - 1].values[kNormal], after = rows[k].values[kNormal];
    EXPECT_LT(std::abs(after - before), 0.05 * before) << name << " t = " << rows[k].time;
  }
}

// The die is at x = 2.5 + 2 (t - 1) while it slides: its mirror position is at time 4 - t.
std::map<long, const test::KeyedRow *> byTenthOfTime(const std::vector<test::KeyedRow> &rows) {
  std::map<long, const test::KeyedRow *> m;
  // Only rows on a tenth: a step cut back to 0.05 puts a row at 1.05, which must not stand for 1.0 or 1.1.
  for (const auto &r : rows)
    if (std::abs(10.0 * r.time - std::round(10.0 * r.time)) < 1e-6) m[std::lround(10.0 * r.time)] = &r;
  return m;
}

} // namespace

TEST(Ironing, WithFrictionTheTangentialForceIsMuTimesTheNormalWhileSliding) {
  const auto h = ironing(mu, "ironing_friction");
  int sliding = 0;
  for (const auto &r : h.contact) {
    if (r.time < 2.0 - 1e-9) continue;  // the die slides 2 per unit time: two units of sliding
    const double N = r.values[kNormal], T = r.values[kTangential];
    ASSERT_GT(N, 0.0) << "t = " << r.time;
    EXPECT_NEAR(T / N, mu, 0.02 * mu) << "t = " << r.time;
    ++sliding;
  }
  EXPECT_GE(sliding, 10);
  expectSmoothWhileSliding(h.contact, "friction");
}

TEST(Ironing, WithoutFrictionTheHistoryIsMirrorSymmetricAboutTheSlabsMiddle) {
  const auto h = ironing(0.0, "ironing_frictionless");
  for (const auto &r : h.contact) EXPECT_EQ(r.values[kTangential], 0.0) << "t = " << r.time;
  expectSmoothWhileSliding(h.contact, "frictionless");
  const auto contact = byTenthOfTime(h.contact), top = byTenthOfTime(h.top);
  int pairs = 0;
  for (long tenth = 10; tenth <= 20; ++tenth) {
    const auto a = contact.find(tenth), b = contact.find(40 - tenth);
    if (a == contact.end() || b == contact.end()) continue;
    // Both ends meet the gap tolerance (1e-3 h) and Newton's; measured 1.5e-4 relative.
    const double N = a->second->values[kNormal], mirrored = b->second->values[kNormal];
    EXPECT_NEAR(mirrored, N, 1e-3 * N) << "t = " << tenth / 10.0;
    const double fx = top.at(tenth)->values[kFx], fxMirrored = top.at(40 - tenth)->values[kFx];
    EXPECT_NEAR(fxMirrored, -fx, 1e-3 * N) << "t = " << tenth / 10.0;
    ++pairs;
  }
  EXPECT_EQ(pairs, 11);
}
