#pragma once
// Each tissue's augmentation (doc/theory.md, eq. 7): kappa_AL = penalty ratio x mu, the
// augmented-Lagrangian rule with the tissue's physical volumetric law, and the volumetric law the
// tangent carries (kappa_t: kappa kappa_AL / (kappa + kappa_AL) with the augmented Lagrangian, the
// material's own with a penalty, none with the mixed method, whose pressure unknowns carry it).
//
// What changes during a run lives here, with the one that changes it: the Uzawa loop raises a
// tissue's ratio where its loop contracts slowly (UzawaLoop::kAugmentationGrowth), and a restart
// restores the ratios. The assembly reads the tangent laws by reference (the Assembler is given
// tangentLaws() when built), so a raise reaches every later evaluation; the scene's laws stay the
// physical ones. No Trilinos.

#include <cstddef>
#include <vector>

#include "materials/VolumetricEnergy.hpp"
#include "solvers/incompressibility/AugmentedLagrangianRule.hpp"
#include "solvers/parameters/IncompressibilityParameters.hpp"

namespace glossa::solvers {

class Augmentation {
public:
  // Per tissue: its physical volumetric law (kappa = inf for nu = 0.5) and its matrix's shear
  // modulus. io::DeckError for a penalty with an infinite bulk modulus.
  Augmentation(const IncompressibilityParameters &parameters, std::vector<materials::VolumetricEnergy> physical,
               std::vector<double> mu);

  // kappa_AL = penalty ratio x mu.
  static double augmentationKappa(const IncompressibilityParameters &parameters, double mu);
  // kappa in the tangent for a material's kappa (io::DeckError if a penalty would need kappa = inf).
  static double tangentKappa(const IncompressibilityParameters &parameters, double materialKappa, double mu);

  std::size_t tissues() const { return physical_.size(); }
  const materials::VolumetricEnergy &physicalLaw(std::size_t tissue) const { return physical_[tissue]; }
  // The laws the tangent carries, one per tissue (stable storage: the assembly holds a reference).
  const std::vector<materials::VolumetricEnergy> &tangentLaws() const { return tangent_; }
  const AugmentedLagrangianRule &rule(std::size_t tissue) const { return rules_[tissue]; }
  // kappa_AL / mu of each tissue now.
  const std::vector<double> &ratios() const { return ratio_; }
  double mu(std::size_t tissue) const { return mu_[tissue]; }

  // A tissue's kappa_AL / mu from now on, with its rule and, with the augmented Lagrangian, its
  // tangent law.
  void setRatio(std::size_t tissue, double ratio);

  // The law of the constrained problem that the Uzawa loop converges to, for its tangent
  // (ConstrainedTangent): the physical one, its bulk modulus capped at kConstrainedRatio mu
  // (infinite for nu = 0.5; the cap moves a limit point by about 1e-5 of its load, below).
  // `ratio`: another cap (ratio mu), e.g. the controller's sensitivities' (ControllerParameters).
  static constexpr double kConstrainedRatio = 1e4;
  materials::VolumetricEnergy constrainedLaw(std::size_t tissue, double ratio = kConstrainedRatio) const;
  // Puts `laws` (one per tissue) in the tangent's place and returns the laws it held; the storage
  // the assembly reads stays the same. For ConstrainedTangent, which puts them back.
  std::vector<materials::VolumetricEnergy> exchangeTangentLaws(std::vector<materials::VolumetricEnergy> laws);

private:
  IncompressibilityParameters parameters_;
  std::vector<materials::VolumetricEnergy> physical_, tangent_;
  std::vector<double> mu_, ratio_;
  std::vector<AugmentedLagrangianRule> rules_;
};

} // namespace glossa::solvers
