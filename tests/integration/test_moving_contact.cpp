// A moving obstacle in a deck (inputs/verification/moving_plane_block.xml): the rigid plane on
// top of a block on rollers moves down by delta along a ramp; frictionless, by the augmented
// Lagrangian with a 1e-12 m gap tolerance. The top must follow the plane exactly: every traced top
// node is at -delta t at every step, to the gap tolerance. The independent reference for the force
// is the same block compressed by a prescribed displacement -delta t of its top (the deck with its
// contact replaced by a Dirichlet condition): the contact's normal force and the top's resultant
// equal that run's reaction to 1e-6, and the rollers' reaction balances them.
#include <cmath>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {

const double delta = 1e-4;

// The deck with its Contact section replaced by the top's prescribed displacement.
std::string prescribedTopDeck(const std::filesystem::path &dir) {
  std::ifstream in(test::inputPath("verification/moving_plane_block.xml"));
  std::stringstream s;
  s << in.rdbuf();
  std::string deck = s.str();
  const auto begin = deck.find("  <ParameterList name=\"Contact\">");
  const auto end = deck.find("  <ParameterList name=\"Named points\">");
  EXPECT_NE(begin, std::string::npos);
  deck.replace(begin, end - begin, "");
  const std::string bc = R"xml(    <ParameterList name="top">
      <Parameter name="node set" type="string" value="zmax"/>
      <Parameter name="components" type="string" value="z"/>
      <Parameter name="value" type="Array(double)" value="{0, 0, -1e-4}"/>
      <ParameterList name="time function">
        <Parameter name="type" type="string" value="ramp"/>
      </ParameterList>
    </ParameterList>
)xml";
  deck.insert(deck.find("  </ParameterList>\n  <ParameterList name=\"Named points\">"), bc);
  std::filesystem::create_directories(dir);
  const auto file = dir / "prescribed_top.xml";
  std::ofstream(file) << deck;
  return file.string();
}

} // namespace

TEST(MovingContact, PlaneMovedByARampPushesTheBlockByExactlyItsDisplacement) {
  const auto output = test::scratchDirectory("moving_plane_block");
  const auto s = test::runDeck(test::inputPath("verification/moving_plane_block.xml"), {}, output);
  ASSERT_TRUE(s.at("converged").get<bool>());
  EXPECT_TRUE(s.at("contact").at("gap_tolerance_met").get<bool>());
  int rows = 0;
  for (const auto &r : test::readTraces(output / "traces.csv")) {
    if (r.point.rfind("top", 0) != 0) continue;  // the box's own 'origin' is traced too
    EXPECT_NEAR(r.u[2], -delta * r.time, 1e-12) << r.point << " at t = " << r.time;
    ++rows;
  }
  EXPECT_EQ(rows, 3 * 5);  // three points, t = 0 and four steps

  const auto reference = test::scratchDirectory("moving_plane_block_prescribed");
  const auto r = test::runDeck(prescribedTopDeck(reference), {}, reference / "run");
  ASSERT_TRUE(r.at("converged").get<bool>());
  const auto reactions = test::readKeyedCsv(reference / "run" / "reactions.csv");
  const auto contact = test::readKeyedCsv(output / "contact.csv").at("press");
  const auto top = test::readKeyedCsv(output / "resultants.csv").at("zmax");
  const auto bottom = test::readKeyedCsv(output / "reactions.csv").at("bottom");
  const auto &prescribed = reactions.at("top");
  ASSERT_EQ(contact.size(), prescribed.size());
  for (std::size_t k = 1; k < contact.size(); ++k) {
    // The prescribed top's reaction pulls down (-z); the plane pushes down too.
    const double force = -prescribed[k].values[2];
    ASSERT_GT(force, 0.0);
    EXPECT_NEAR(contact[k].values[1], force, 1e-6 * force) << "t = " << contact[k].time;
    EXPECT_NEAR(-top[k].values[2], force, 1e-6 * force) << "t = " << contact[k].time;
    EXPECT_NEAR(bottom[k].values[2], force, 1e-6 * force) << "t = " << contact[k].time;
    EXPECT_EQ(contact[k].values[5], 0.0);  // frictionless: no tangential force
  }
}

// Tied contact (friction = tied, penalty 1e10 Pa/m): the plane presses the top down by delta, then
// pulls it back up to +delta. Each point stays where it touched: at t = 1 every traced top node is
// at +delta to within the penalty's offset |t| / eps (|t| the mean normal traction), the contact
// carries tension (a negative normal force) that the rollers balance, and the tied top, kept from
// shrinking sideways, carries a tangential force.
TEST(MovingContact, TiedPlanePullsTheBlockUpAfterPressingIt) {
  const auto output = test::scratchDirectory("moving_plane_block_tied");
  const double eps = 1e10;
  const auto s = test::runDeck(test::inputPath("verification/moving_plane_block.xml"),
                               {"Contact/press/friction=tied", "Contact/press/penalty=1e10", "Contact/press/enforcement=penalty",
                                "Contact/press/translation z time function/type=table",
                                "Contact/press/translation z time function/times={0, 0.5, 1}",
                                "Contact/press/translation z time function/values={0, 1, -1}"},
                               output);
  ASSERT_TRUE(s.at("converged").get<bool>());
  const auto contact = test::readKeyedCsv(output / "contact.csv").at("press");
  const auto bottom = test::readKeyedCsv(output / "reactions.csv").at("bottom");
  const auto &last = contact.back().values;
  ASSERT_EQ(contact.back().time, 1.0);
  const double N = last[1], area = last[0];
  EXPECT_LT(N, 0.0);
  EXPECT_NEAR(bottom.back().values[2], N, 1e-6 * std::abs(N));
  EXPECT_GT(last[5], 0.0);
  for (const auto &r : test::readTraces(output / "traces.csv")) {
    if (r.time != 1.0 || r.point.rfind("top", 0) != 0) continue;
    EXPECT_NEAR(r.u[2], delta, 3.0 * std::abs(N) / area / eps) << r.point;
  }
}
