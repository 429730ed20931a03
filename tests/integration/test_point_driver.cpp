// glossa point against closed forms computed here, independently of the material code:
//  - passive fibres along e under incompressible uniaxial stretch: the axial stress
//    sigma_11 - sigma_22 = 2 A B e^{B(I1-3)} (l^2 - 1/l) + phi l T0max 2 a A (l-1) e^{a (l-1)^2};
//  - neo-Hookean simple shear: sigma_12 = mu gamma, sigma_11 - sigma_22 = mu gamma^2,
//    psi = mu gamma^2 / 2;
//  - an active fibre held at F = 1 (table path): alpha follows 1 - e^{-t/tau} within the
//    backward-Euler bound and T between 0.96 and 1 of T0s T0max alpha (T0s = 0.1);
//  - a table whose row count does not match is a deck error naming the parameter.
#include <cmath>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "CsvRows.hpp"
#include "RunDeck.hpp"
#include "app/PointCommand.hpp"
#include "io/deck/DeckError.hpp"
#include "solvers/parameters/RunConfiguration.hpp"

using namespace glossa;

namespace {
using Table = std::vector<std::map<std::string, double>>;

Table runPoint(const std::vector<std::string> &overrides, const std::string &tag) {
  const auto schema = app::deckSchema();
  auto deck = io::Deck::fromFile(test::inputPath("materials/muscle_point.xml"));
  for (const auto &o : overrides) deck.applyOverride(o, schema);
  deck.validate(schema);
  const auto file = test::scratchDirectory("point") / (tag + ".csv");
  const int rows = app::runPointDriver(deck, solvers::parseRunConfiguration(deck).time, file);
  const Table table = test::readCsvRows(file);
  EXPECT_EQ(static_cast<int>(table.size()), rows);
  return table;
}
} // namespace

TEST(PointDriver, PassiveFibreUniaxialMatchesTheClosedForm) {
  const double A = 1652.0, B = 0.6265, T0max = 668.8e3, a = 12.43, Ap = 8.568e-4, phi = 0.7;
  const auto t = runPoint({"Material/Fibre families/axial/muscle group=", "Point/amplitude=0.3"}, "passive");
  ASSERT_EQ(t.size(), 101u);
  for (const auto &row : t) {
    const double l = 1.0 + row.at("path_parameter"), I1 = l * l + 2.0 / l;
    const double exact = 2 * A * B * std::exp(B * (I1 - 3)) * (l * l - 1 / l) +
                         (l > 1 ? phi * l * T0max * 2 * a * Ap * (l - 1) * std::exp(a * (l - 1) * (l - 1)) : 0.0);
    EXPECT_NEAR(row.at("axial_stress"), exact, 1e-9 * std::max(1.0, exact)) << "lambda " << l;
    EXPECT_NEAR(row.at("lambda_f_axial"), l, 1e-12);
  }
  EXPECT_GT(t.back().at("axial_stress"), 1e4);
}

TEST(PointDriver, NeoHookeanSimpleShear) {
  const double mu = 1000.0;
  // The deck's fibre family is given no volume: the neo-Hookean matrix alone.
  const auto t = runPoint({"Material/type=neo-Hookean", "Material/shear modulus=1000",
                           "Material/Fibre law/total fibre fraction=0", "Point/path=simple shear",
                           "Point/amplitude=0.8", "Point/shear plane normal=0,1,0"},
                          "shear");
  for (const auto &row : t) {
    const double g = row.at("path_parameter");
    EXPECT_NEAR(row.at("sigma_xy"), mu * g, 1e-9 * mu);
    EXPECT_NEAR(row.at("sigma_xx") - row.at("sigma_yy"), mu * g * g, 1e-9 * mu);
    EXPECT_NEAR(row.at("energy"), 0.5 * mu * g * g, 1e-9 * mu);
  }
  EXPECT_NEAR(t.back().at("path_parameter"), 0.8, 1e-15);
}

TEST(PointDriver, IsometricActivationAtAPoint) {
  const double T0max = 668.8e3, tau = 0.150, dt = 0.005;
  const double T0s = 0.1;
  const auto t = runPoint({"Point/path=table", "Point/times=0", "Point/F=1,0,0,0,1,0,0,0,1",
                           "Material/Muscle groups/fibres/T0s=0.1"},
                          "isometric");
  for (const auto &row : t) {
    const double alpha = row.at("alpha_fibres"), exact = 1 - std::exp(-row.at("time") / tau);
    EXPECT_LE(std::abs(alpha - exact), dt / (2 * std::exp(1.0) * tau) * (1 + dt / tau));
    EXPECT_LE(row.at("T_axial"), T0s * T0max * alpha * (1 + 1e-12));
    EXPECT_GE(row.at("T_axial"), 0.96 * T0s * T0max * alpha);
    EXPECT_LE(row.at("lambda_c_axial"), 1.0); // the series element stretches, the contractile shortens
  }
}

TEST(PointDriver, TableOfTheWrongSizeIsADeckError) {
  try {
    runPoint({"Point/path=table", "Point/times=0,1", "Point/F=1,0,0,0,1,0,0,0,1"}, "bad");
    FAIL() << "expected a DeckError";
  } catch (const io::DeckError &e) {
    EXPECT_NE(std::string(e.what()).find("Point/F"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("needs 9 values per entry of 'times' (2 times, 9 values)"), std::string::npos)
        << e.what();
  }
}

// The point's material needs no mesh: a radial fan is evaluated at the point's position. With the
// fan's centre at the origin and the point on the y axis, the fibre is along y, across a uniaxial
// stretch lambda along x: lambda_f = 1 / sqrt(lambda) (incompressible, transversely isotropic).
TEST(PointDriver, RadialFanIsEvaluatedAtThePointsPosition) {
  const auto t = runPoint({"Material/Fibre families/axial/direction field=radial fan",
                           "Material/Fibre families/axial/fan centre=0,0,0", "Point/position=0,0.01,0"},
                          "fan");
  ASSERT_GT(t.size(), 2u);
  for (const auto &row : t)
    EXPECT_NEAR(row.at("lambda_f_axial"), 1.0 / std::sqrt(1.0 + row.at("path_parameter")), 1e-12);
}

TEST(PointDriver, DirectionFieldsSampledFromAMeshAreDeckErrors) {
  try {
    runPoint({"Material/Fibre families/axial/direction field=polylines"}, "polylines");
    FAIL() << "expected a DeckError";
  } catch (const io::DeckError &e) {
    EXPECT_NE(std::string(e.what()).find("Material/Fibre families/axial/direction field"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("glossa point takes constant or radial fan"), std::string::npos) << e.what();
  }
}
