// Inexact Uzawa (loose Newton solves while the multipliers are far from their fixed point) reaches
// the same multipliers and displacement as the plain nested loop: the element pressure field
// (p_e, of which Lambda_e = beta p_e at the fixed point) and the whole displacement field of the
// last step, read from results.h5, agree to the effect of the dilatation tolerance.
#include <gtest/gtest.h>

#include <cmath>

#include "LastStepField.hpp"
#include "RunDeck.hpp"

using namespace glossa;
using test::lastStepField;
using test::maxAbs;

namespace {

int total(const nlohmann::json &s, const std::string &key) {
  int n = 0;
  for (const auto &step : s.at("steps")) n += step.at(key).get<int>();
  return n;
}
}  // namespace

TEST(UzawaAcceleration, InexactReachesThePlainLoopsMultipliersAndDisplacement) {
  for (const std::string nu : {"0.5", "0.4999"}) {
    std::vector<std::string> common = {"Mesh/Box/cells=4,4,4", "Material/Poisson's ratio=" + nu,
                                       "Incompressibility/method=augmented Lagrangian",
                                       "Incompressibility/dilatation tolerance=1e-9", "Output/every=10"};
    auto plain = common, inexact = common;
    plain.push_back("Incompressibility/Uzawa acceleration=none");
    inexact.push_back("Incompressibility/Uzawa acceleration=inexact");
    const auto dirPlain = test::scratchDirectory("uzawa_plain"),
               dirInexact = test::scratchDirectory("uzawa_inexact");
    const auto a = test::runDeck(test::inputPath("verification/step44_block.xml"), plain, dirPlain);
    const auto b = test::runDeck(test::inputPath("verification/step44_block.xml"), inexact, dirInexact);
    ASSERT_TRUE(a.at("converged").get<bool>() && b.at("converged").get<bool>()) << nu;

    const auto pa = lastStepField(dirPlain, "pressure"), pb = lastStepField(dirInexact, "pressure");
    const auto ua = lastStepField(dirPlain, "displacement"), ub = lastStepField(dirInexact, "displacement");
    ASSERT_EQ(pa.size(), 64u);
    ASSERT_EQ(pa.size(), pb.size());
    ASSERT_EQ(ua.size(), ub.size());
    // A dilatation error of 1e-9 moves p by about kappa_AL x 1e-9 = 1e-7 mu, u by ~1e-9 relative.
    for (std::size_t i = 0; i < pa.size(); ++i)
      EXPECT_NEAR(pa[i], pb[i], 1e-7 * maxAbs(pa)) << nu << " element " << i;
    for (std::size_t i = 0; i < ua.size(); ++i)
      EXPECT_NEAR(ua[i], ub[i], 1e-7 * maxAbs(ua)) << nu << " dof " << i;
    EXPECT_GT(maxAbs(pa), 1e8) << "the pressure under the 400 MPa patch";
    EXPECT_LT(total(b, "newton_iterations"), total(a, "newton_iterations")) << nu;
  }
}
