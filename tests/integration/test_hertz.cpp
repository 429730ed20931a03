// Hertz's cylinder on a rigid plane through the full solve (inputs/verification/hertz_*.xml,
// doc/contact.md "Hertz"): a neo-Hookean cylinder in plane strain pressed onto a rigid plane at a
// small load, compressible (nu = 0.3) and nearly incompressible (nu = 0.4999, augmented
// Lagrangian). The contact half-width and the peak pressure, measured on the contact_pressure
// field (HertzContact.hpp), are compared with Hertz's a = sqrt(4 P R / (pi E*)) and
// p0 = 2 P / (pi a), computed from the deck's radius, shear modulus and Poisson's ratio and the
// load P the plane carried: on three meshes whose fine band has 8, 16 and 32 cells (5, 11 and 21
// per a) both errors fall at every refinement, and on the finest both are within 3 %.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "HertzContact.hpp"

using namespace glossa;

namespace {

test::HertzRun run(const std::string &deck, double scale, const std::string &rule, const std::string &name) {
  const auto r = test::runHertz(test::inputPath("verification/" + deck), scale, rule, test::scratchDirectory(name));
  std::printf("%s, %s points, %d elements: a_Hertz %.5f mm, a error %+.2f %%; p0_Hertz %.2f Pa, p0 error %+.2f %%; "
              "deviation %.4f, oscillation %.4f (of p0); Newton %d, Uzawa %d, contact updates %d; %.1f s\n",
              deck.c_str(), rule.c_str(), r.elements, 1e3 * r.hertz.a, 100 * r.errorA(), r.hertz.p0,
              100 * r.errorP0(), r.measured.deviation, r.measured.oscillation, r.newton, r.uzawa, r.contactUpdates,
              r.seconds);
  // Hertz is linear theory: the load must keep the contact narrow and the strain small.
  EXPECT_LE(r.hertz.a / r.radius, 0.1) << name;
  EXPECT_LE(r.hertz.p0 / r.eStar, 0.05) << name << ": the largest strain, about p0 / E*";
  EXPECT_TRUE(r.gapToleranceMet) << name;
  return r;
}

// The deck's mesh and the meshes with a half and a quarter of its counts.
std::vector<test::HertzRun> expectConvergenceToHertz(const std::string &deck, const std::string &name) {
  std::vector<test::HertzRun> runs;
  for (double scale : {0.25, 0.5, 1.0})
    runs.push_back(run(deck, scale, "gauss", name + "_" + std::to_string(runs.size())));
  for (std::size_t i = 1; i < runs.size(); ++i) {
    EXPECT_LT(std::abs(runs[i].errorA()), std::abs(runs[i - 1].errorA())) << name << ", mesh " << i;
    EXPECT_LT(std::abs(runs[i].errorP0()), std::abs(runs[i - 1].errorP0())) << name << ", mesh " << i;
  }
  EXPECT_LE(std::abs(runs.back().errorA()), 0.03) << name << ": half-width, finest mesh";
  EXPECT_LE(std::abs(runs.back().errorP0()), 0.03) << name << ": peak pressure, finest mesh";
  return runs;
}

} // namespace

TEST(Hertz, CompressibleCylinderConvergesToHertz) { expectConvergenceToHertz("hertz_cylinder.xml", "hertz"); }

// nu = 0.4999 under the augmented Lagrangian: the one Uzawa loop ends every step with the dilatation
// error (default tolerance 1e-3) and the gap (run() checks the summary) both within tolerance.
TEST(Hertz, NearlyIncompressibleCylinderConvergesToHertz) {
  for (const auto &r : expectConvergenceToHertz("hertz_cylinder_incompressible.xml", "hertz_incompressible"))
    EXPECT_LE(r.maxDilatationError, 1e-3);
}

// Gauss or nodal contact points on the middle mesh (11 band cells per a): the 2 x 2 Gauss points of
// a face, each pressed by its own gap, make the pressure zig-zag from node to node; the nodal rule's
// one point per node does not. Measured (doc/contact.md): the second difference of the deviation
// from Hertz's ellipse, 0.013 p0 with Gauss points against 0.0006 p0 with nodal ones.
TEST(Hertz, NodalContactPointsGiveTheSmootherPressureProfile) {
  const auto gauss = run("hertz_cylinder.xml", 0.5, "gauss", "hertz_rule_gauss");
  const auto nodal = run("hertz_cylinder.xml", 0.5, "nodal", "hertz_rule_nodal");
  EXPECT_LT(nodal.measured.oscillation, 0.2 * gauss.measured.oscillation);
  EXPECT_LE(std::abs(nodal.errorA()), 0.03);
  EXPECT_LE(std::abs(nodal.errorP0()), 0.03);
}
