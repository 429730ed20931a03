// Contact with near-incompressibility (inputs/verification/indentation_nearly_incompressible.xml,
// doc/contact.md "A nearly incompressible block on a sphere"): a neo-Hookean block at nu = 0.49999
// pressed onto a rigid sphere by its far face.
//  (a) With the augmented Lagrangian for both the volume and the contact, every step ends, in one
//      Uzawa loop and without a cut-back, with the dilatation error within 0.1 % and the gap
//      error within the contact's gap tolerance.
//  (b) The force equals the mixed method's (element pressures as unknowns, the discrete constraint
//      met to round-off) on the same mesh to 1 %. This compares two methods of this solver; the
//      independent check beside it is equilibrium: the sphere's push on the bottom (its face
//      set's resultant) equals the far face's reaction. Hertz's formula is not asserted here: on
//      this 2 x 2 x 1 mm block the contact radius is a third of the half-width and the force
//      lies 16 % above Hertz's half-space (the size effect is measured in bench/, doc/contact.md).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {
const char *kDeck = "verification/indentation_nearly_incompressible.xml";
const int kSteps = 4;           // the deck's end time / step size
const double kGapTolerance = 1e-3 * 1e-3 / 8; // the default: 1e-3 of the bottom faces' edge (1 mm / 8)

struct IndentationRun {
  nlohmann::json summary;
  double force = 0; // the full block's: 4 x the quarter's far-face reaction [N]
  int uzawa = 0, newton = 0;
};

IndentationRun indent(const std::string &method, const std::string &name) {
  const auto output = test::scratchDirectory(name);
  IndentationRun r;
  r.summary = test::runDeck(test::inputPath(kDeck), {"Incompressibility/method=" + method}, output);
  EXPECT_TRUE(r.summary.at("converged").get<bool>()) << method;
  const auto resultants = test::readKeyedCsv(output / "resultants.csv");
  const double top = resultants.at("zmax").back().values[2], bottom = resultants.at("zmin").back().values[2];
  r.force = -4.0 * top;
  // Equilibrium: the symmetry planes carry no z force, so the sphere's push is the far face's pull.
  EXPECT_NEAR(bottom, -top, 1e-6 * std::abs(top)) << method;
  for (const auto &step : r.summary.at("steps")) {
    r.uzawa += step.at("uzawa_iterations").get<int>();
    r.newton += step.at("newton_iterations").get<int>();
  }
  return r;
}
} // namespace

TEST(ContactNearIncompressible, AugmentedLagrangianMeetsVolumeAndGapInOneLoopAndAgreesWithMixed) {
  const IndentationRun al = indent("augmented Lagrangian", "indentation_ni_al");
  const IndentationRun mixed = indent("mixed", "indentation_ni_mixed");
  // (a) every step in one loop (a cut-back would add steps), both tolerances met at its end.
  const auto &steps = al.summary.at("steps");
  ASSERT_EQ(steps.size(), static_cast<std::size_t>(kSteps));
  for (const auto &step : steps) {
    const double t = step.at("time").get<double>();
    EXPECT_LE(step.at("max_dilatation_error").get<double>(), 1e-3) << "t = " << t;
    const auto &sphere = step.at("contacts").at("sphere");
    EXPECT_TRUE(sphere.at("gap_met").get<bool>()) << "t = " << t;
    EXPECT_LE(sphere.at("largest_gap_error").get<double>(), kGapTolerance) << "t = " << t;
    EXPECT_GT(sphere.at("active_points").get<int>(), 0) << "t = " << t;
  }
  EXPECT_TRUE(al.summary.at("contact").at("gap_tolerance_met").get<bool>());
  // (b) the same discrete problem: the augmented Lagrangian stops within its tolerances of it.
  ASSERT_GT(mixed.force, 0.0);
  EXPECT_NEAR(al.force, mixed.force, 1e-2 * mixed.force);
  std::printf("force: augmented Lagrangian %.6e N, mixed %.6e N (relative difference %.2e); augmented Lagrangian "
              "%d Uzawa solves, %d Newton iterations; mixed %d, %d\n",
              al.force, mixed.force, std::abs(al.force - mixed.force) / mixed.force, al.uzawa, al.newton, mixed.uzawa,
              mixed.newton);
}
