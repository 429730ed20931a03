// Each tissue's augmentation (solvers/incompressibility/Augmentation): the tangent's kappa_t per
// method against its closed form, a raise that changes the rule and the tangent of that tissue
// alone (the reference the assembly holds sees it), and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "io/deck/DeckError.hpp"
#include "materials/VolumetricEnergy.hpp"
#include "solvers/incompressibility/Augmentation.hpp"

using namespace glossa;
using materials::VolumetricEnergy;
using solvers::Augmentation;
using solvers::IncompressibilityMethod;

namespace {
constexpr double kMu = 2e3;

solvers::IncompressibilityParameters method(IncompressibilityMethod m) {
  solvers::IncompressibilityParameters p;
  p.method = m;
  return p; // penalty ratio 30
}

VolumetricEnergy law(double kappa) { return VolumetricEnergy(VolumetricEnergy::Form::SimoTaylor, kappa); }
} // namespace

TEST(Augmentation, TheTangentCarriesKappaTOfEachMethod) {
  const double kappa = 5000.0 * kMu, kappaAL = 30.0 * kMu;
  const Augmentation al(method(IncompressibilityMethod::augmentedLagrangian), {law(kappa)}, {kMu});
  EXPECT_NEAR(al.tangentLaws()[0].kappa(), kappa * kappaAL / (kappa + kappaAL), 1e-9 * kappaAL);
  EXPECT_EQ(al.physicalLaw(0).kappa(), kappa); // the physical law is kept as given
  EXPECT_EQ(al.ratios()[0], 30.0);
  const Augmentation exact(method(IncompressibilityMethod::augmentedLagrangian),
                           {law(std::numeric_limits<double>::infinity())}, {kMu});
  EXPECT_EQ(exact.tangentLaws()[0].kappa(), kappaAL); // nu = 0.5: kappa_t = kappa_AL
  const Augmentation penalty(method(IncompressibilityMethod::penalty), {law(kappa)}, {kMu});
  EXPECT_EQ(penalty.tangentLaws()[0].kappa(), kappa);
  const Augmentation mixed(method(IncompressibilityMethod::mixed), {law(kappa)}, {kMu});
  EXPECT_EQ(mixed.tangentLaws()[0].kappa(), 0.0); // the pressure unknowns carry the law
}

TEST(Augmentation, ARaiseChangesThatTissuesRuleAndTangentOnly) {
  const double kappa = 5000.0 * kMu;
  Augmentation a(method(IncompressibilityMethod::augmentedLagrangian), {law(kappa), law(kappa)}, {kMu, 2.0 * kMu});
  const std::vector<VolumetricEnergy> &held = a.tangentLaws(); // as the assembly holds it
  const double before = held[0].kappa(), other = held[1].kappa();
  a.setRatio(0, 300.0);
  const double kappaAL = 300.0 * kMu;
  EXPECT_NEAR(held[0].kappa(), kappa * kappaAL / (kappa + kappaAL), 1e-9 * kappaAL);
  EXPECT_GT(held[0].kappa(), before);
  EXPECT_EQ(held[1].kappa(), other);
  EXPECT_EQ(a.ratios()[0], 300.0);
  EXPECT_EQ(a.rule(0).tangentKappa(), held[0].kappa());
  EXPECT_EQ(held[0].form(), VolumetricEnergy::Form::SimoTaylor); // the tissue's own form
  EXPECT_THROW(a.setRatio(2, 1.0), std::out_of_range);
}

TEST(Augmentation, APenaltyAtNuOneHalfIsRefused) {
  EXPECT_THROW(Augmentation(method(IncompressibilityMethod::penalty), {law(std::numeric_limits<double>::infinity())},
                            {kMu}),
               io::DeckError);
  EXPECT_THROW(Augmentation(method(IncompressibilityMethod::augmentedLagrangian), {law(1.0)}, {kMu, kMu}),
               std::invalid_argument);
}

// The constrained problem's laws (ConstrainedTangent): the physical law where it is finite and
// below the cap, the cap of 1e4 mu for nu = 0.5; exchanged into the storage the assembly holds
// and back, unchanged, the rules untouched.
TEST(Augmentation, TheConstrainedLawsAreExchangedIntoTheTangentsStorageAndBack) {
  const double kappa = 5000.0 * kMu, infinite = std::numeric_limits<double>::infinity();
  Augmentation al(method(IncompressibilityMethod::augmentedLagrangian), {law(kappa), law(infinite)}, {kMu, 2.0 * kMu});
  EXPECT_EQ(al.constrainedLaw(0).kappa(), kappa);
  EXPECT_EQ(al.constrainedLaw(1).kappa(), Augmentation::kConstrainedRatio * 2.0 * kMu);
  EXPECT_EQ(al.constrainedLaw(1).form(), VolumetricEnergy::Form::SimoTaylor);
  // Another cap (the gradient controller's sensitivities): the lower of it and the physical law.
  EXPECT_EQ(al.constrainedLaw(1, 1e3).kappa(), 1e3 * 2.0 * kMu);
  EXPECT_EQ(al.constrainedLaw(0, 1e3).kappa(), 1e3 * kMu);
  EXPECT_EQ(al.constrainedLaw(0, 1e5).kappa(), kappa);
  const std::vector<VolumetricEnergy> &held = al.tangentLaws(); // the assembly's reference
  const double kappaT0 = held[0].kappa(), kappaT1 = held[1].kappa();
  auto augmented = al.exchangeTangentLaws({al.constrainedLaw(0), al.constrainedLaw(1)});
  EXPECT_EQ(held[0].kappa(), kappa);
  EXPECT_EQ(held[1].kappa(), Augmentation::kConstrainedRatio * 2.0 * kMu);
  EXPECT_EQ(al.rule(1).tangentKappa(), kappaT1); // the Uzawa rule stays the augmented one
  al.exchangeTangentLaws(std::move(augmented));
  EXPECT_EQ(held[0].kappa(), kappaT0);
  EXPECT_EQ(held[1].kappa(), kappaT1);
  EXPECT_THROW(al.exchangeTangentLaws({law(kappa)}), std::invalid_argument);
}
