// glossa point on a small deck: an incompressible neo-Hookean point stretched uniaxially gives
// the closed forms sigma_11 - sigma_22 = mu (lambda^2 - 1/lambda) and
// psi = mu/2 (lambda^2 + 2/lambda - 3) at every step of the deck's Time section; a deck the
// driver refuses leaves no file behind.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "ProcessScratch.hpp"

#include "CsvRows.hpp"
#include "DeckOnFile.hpp"
#include "app/DeckSchema.hpp"
#include "app/PointCommand.hpp"
#include "solvers/parameters/RunConfiguration.hpp"

namespace glossa::app {
namespace {

const double kMu = 1000.0;

io::Deck neoHookeanDeck(const std::string &name, const std::vector<std::string> &overrides = {}) {
  return test::deckOnFile(name, R"X(<ParameterList name="Material">
  <Parameter name="type" type="string" value="neo-Hookean"/>
  <Parameter name="shear modulus" type="double" value="1000"/>
</ParameterList>
<ParameterList name="Point">
  <Parameter name="amplitude" type="double" value="0.3"/>
</ParameterList>
<ParameterList name="Time">
  <Parameter name="step size" type="double" value="0.25"/>
</ParameterList>
)X",
                          deckSchema(), overrides);
}


TEST(PointCommand, NeoHookeanUniaxialStretchAtEveryStep) {
  const io::Deck deck = neoHookeanDeck("point_neo_hookean.xml");
  const auto csv = test::processScratch() / "point_neo_hookean.csv";
  const int written = runPointDriver(deck, solvers::parseRunConfiguration(deck).time, csv);
  const auto rows = test::readCsvRows(csv);
  ASSERT_EQ(written, 5); // t = 0, 0.25, 0.5, 0.75, 1
  ASSERT_EQ(rows.size(), 5u);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto &row = rows[k];
    const double t = 0.25 * static_cast<double>(k), lambda = 1.0 + 0.3 * t; // the default ramp over the end time
    EXPECT_NEAR(row.at("time"), t, 1e-15);
    EXPECT_NEAR(row.at("path_parameter"), lambda - 1.0, 1e-15);
    EXPECT_NEAR(row.at("axial_stress"), kMu * (lambda * lambda - 1.0 / lambda), 1e-9 * kMu) << "t = " << t;
    EXPECT_NEAR(row.at("sigma_xx") - row.at("sigma_yy"), kMu * (lambda * lambda - 1.0 / lambda), 1e-9 * kMu);
    EXPECT_NEAR(row.at("sigma_yy"), row.at("sigma_zz"), 1e-9 * kMu);
    EXPECT_NEAR(row.at("sigma_xy"), 0.0, 1e-9 * kMu);
    EXPECT_NEAR(row.at("energy"), 0.5 * kMu * (lambda * lambda + 2.0 / lambda - 3.0), 1e-9 * kMu);
  }
}

TEST(PointCommand, ARefusedDeckWritesNoFile) {
  const io::Deck deck = neoHookeanDeck("point_refused.xml", {"Point/direction=0,0,0"});
  const auto csv = test::processScratch() / "point_refused.csv";
  std::filesystem::remove(csv);
  EXPECT_EQ(test::deckErrorOf([&] { runPointDriver(deck, solvers::parseRunConfiguration(deck).time, csv); }),
            "deck " + test::deckPath("point_refused.xml") +
                " (--set on the command line): parameter 'Point/direction' is zero");
  EXPECT_FALSE(std::filesystem::exists(csv));
}

} // namespace
} // namespace glossa::app
