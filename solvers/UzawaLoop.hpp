#pragma once
// The augmented-Lagrangian loop around each Newton solve (DESIGN.md §1, eq. 7):
//   solve f(u; Lambda) = 0, then Lambda_e <- beta p_e   (AugmentedLagrangianRule)
// until max_e |theta_e - theta_phys(p_e)| is below the tolerance: the element pressure then obeys
// the material's physical volumetric law (theta -> 1 for nu = 0.5). With a moderate kappa_AL in
// the tangent the Krylov solves stay cheap, while the multiplier carries the pressure that a pure
// penalty would need kappa/mu >= 1e6 to produce. In "penalty" mode the loop performs one solve.

#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "assembly/Assembler.hpp"
#include "materials/VolumetricEnergy.hpp"
#include "solvers/AugmentedLagrangianRule.hpp"
#include "solvers/NewtonSolver.hpp"
#include "solvers/SolveStatistics.hpp"

namespace glossa::solvers {

Teuchos::ParameterList incompressibilityParameters();

class UzawaLoop {
public:
  // `physical`: per tissue of the assembler's scene, its volumetric law (kappa = inf for nu = 0.5);
  // each tissue's kappa_AL is the penalty ratio times its matrix's shear modulus.
  UzawaLoop(const assembly::Assembler &assembler, const NewtonSolver &newton, const Teuchos::ParameterList &section,
            const std::vector<materials::VolumetricEnergy> &physical);

  bool augmentedLagrangian() const { return augmented_; }
  bool mixedPressure() const { return mixed_; }
  // kappa_AL = penalty ratio x mu (augmented Lagrangian only).
  static double augmentationKappa(const Teuchos::ParameterList &section, double mu);
  // kappa in the tangent: kappa_t = kappa kappa_AL / (kappa + kappa_AL) in augmented-Lagrangian
  // mode, the material's otherwise (io::DeckError if that is infinite).
  static double tangentKappa(const Teuchos::ParameterList &section, double materialKappa, double mu);

  // Solves at fixed time; u and lambda are updated in place (the caller keeps copies to roll
  // back). `residualTolerance` is absolute.
  UzawaResult solve(assembly::Vector &u, std::vector<double> &lambda, double residualTolerance,
                    const NewtonSolver::IterationCallback &onNewton,
                    const std::function<void(int, const NewtonResult &, const DilatationError &)> &onUzawa) const;

  DilatationError dilatationError(const assembly::ElementFields &fields) const;

private:
  const assembly::Assembler &assembler_;
  const NewtonSolver &newton_;
  bool augmented_;
  bool mixed_;                // element pressures are Newton unknowns (MixedPressureState)
  // Stops on the distance from the physical law, with room for more than one Newton solve
  // (augmented Lagrangian and mixed; a penalty makes one solve and reports |theta - 1|).
  bool measuresPhysicalLaw() const { return augmented_ || mixed_; }
  std::vector<AugmentedLagrangianRule> rules_; // per tissue
  std::vector<int> localTissue_;               // per local element: its tissue
  const AugmentedLagrangianRule &ruleOf(std::size_t localElement) const { return rules_[localTissue_[localElement]]; }
  double tolerance_;
  int maxIterations_;
  bool inexact_;              // Uzawa acceleration = inexact inner solves
  double innerTolerance_;     // their relative residual (and update) tolerance
};

} // namespace glossa::solvers
