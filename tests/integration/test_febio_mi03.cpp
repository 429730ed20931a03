// FEBio's verification case mi03 through the full solve (inputs/verification/febio_mi03.xml):
// one hexahedron of uncoupled Mooney-Rivlin material (C10 = 1, C01 = 10, k = 100, U = k/2 ln^2 J)
// compressed to a stretch of 0.2 with free lateral faces. FEBio's published answer: lateral
// stretch 1.416623835, J = 0.40136462. The deck's traces give the lateral stretch (1 + u_x of the
// corner (1, 1, 1)); the deformation is homogeneous, so the match is to the Newton tolerance.
#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

TEST(FebioMi03, LateralStretchAndVolumeRatioMatchFebio) {
  const auto output = test::scratchDirectory("febio_mi03");
  const auto s = test::runDeck(test::inputPath("verification/febio_mi03.xml"), {}, output);
  ASSERT_TRUE(s.at("converged").get<bool>());
  const auto traces = test::readTraces(output / "traces.csv");
  ASSERT_FALSE(traces.empty());
  const auto &last = traces.back();
  EXPECT_NEAR(last.time, 1.0, 1e-12);
  EXPECT_NEAR(last.u[2], -0.8, 1e-12); // the prescribed compression
  const double lateral = 1.0 + last.u[0];
  EXPECT_NEAR(lateral, 1.416623835, 1e-6);
  EXPECT_NEAR(1.0 + last.u[1], lateral, 1e-12); // the two lateral stretches agree
  EXPECT_NEAR(0.2 * lateral * lateral, 0.40136462, 1e-6);
}

// The volume enclosed by the whole boundary is the body's, J V0 = 0.40136462 (FEBio's J), and
// the resultant on a face set with a Dirichlet condition is that condition's reaction: the
// compressed face z = 1 and the fixed plane z = 0 carry opposite forces (no body force).
TEST(FebioMi03, EnclosedVolumeAndFaceResultants) {
  const auto output = test::scratchDirectory("febio_mi03_outputs");
  const auto s = test::runDeck(test::inputPath("verification/febio_mi03.xml"), {}, output);
  ASSERT_TRUE(s.at("converged").get<bool>());
  const auto volumes = test::readKeyedCsv(output / "volumes.csv");
  ASSERT_EQ(volumes.count("boundary"), 1u);
  EXPECT_NEAR(volumes.at("boundary").back().values[0], 0.40136462, 1e-6);
  const auto resultants = test::readKeyedCsv(output / "resultants.csv");
  const auto reactions = s.at("steps").back().at("reactions");
  const auto compression = reactions.at("compression").get<std::vector<double>>();
  const auto zmax = resultants.at("zmax").back().values, zmin = resultants.at("zmin").back().values;
  ASSERT_GT(std::abs(compression[2]), 1e-2); // a real force (moduli of order 1-100, 80 % compression)
  EXPECT_NEAR(zmax[2], compression[2], 1e-12 * std::abs(compression[2]));
  EXPECT_NEAR(zmin[2], -zmax[2], 1e-9 * std::abs(zmax[2]));
  EXPECT_NEAR(zmin[2], reactions.at("symmetry z").get<std::vector<double>>()[2], 1e-12 * std::abs(zmax[2]));
}
