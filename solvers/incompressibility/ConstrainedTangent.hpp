#pragma once
// The tangent of the constrained problem at a converged Uzawa state, for the stiffness along the
// load path near a limit point (solvers/run/PathWatch, doc/theory.md "Limit points").
//
// The Newton solves of the augmented Lagrangian hold the multipliers fixed, and an element's
// volume change then costs only kappa_t <= kappa_AL (30 mu by default): that inner problem is
// softer than the constrained one and has its own, lower load maximum (the thick sphere's, 0.3 %
// below the constrained problem's at 30 mu; 0.03 % at 300 mu). The state the Uzawa loop converges
// to obeys the physical law, p_e = U_phys'(theta_e), so the linearisation of the converged loop
// carries the physical bulk modulus (infinite for nu = 0.5). While a ConstrainedTangent lives,
// every tissue's tangent law is Augmentation::constrainedLaw, and multipliers() gives each element
// the pressure it has in the state,
//   Lambda_c = p_e - U_c'(theta_e),   p_e = U_t'(theta_e) + Lambda_e,
// so that the residual is the state's and its tangent is the constrained problem's. Its
// destruction restores the augmented laws.

#include <vector>

#include "assembly/ResultEvaluator.hpp"
#include "materials/VolumetricEnergy.hpp"
#include "solvers/incompressibility/Augmentation.hpp"

namespace glossa::solvers {

class ConstrainedTangent {
public:
  // At the state (u, lambda) of the assembler behind `results`, the physical bulk modulus capped
  // at `ratio` mu. Collective (element dilatations).
  ConstrainedTangent(Augmentation &augmentation, const assembly::ResultEvaluator &results, const assembly::Vector &u,
                     const std::vector<double> &lambda, double ratio = Augmentation::kConstrainedRatio);
  ~ConstrainedTangent();
  ConstrainedTangent(const ConstrainedTangent &) = delete;
  ConstrainedTangent &operator=(const ConstrainedTangent &) = delete;

  // Lambda_c per local element.
  const std::vector<double> &multipliers() const { return multipliers_; }

private:
  Augmentation &augmentation_;
  std::vector<materials::VolumetricEnergy> augmented_; // the laws to restore
  std::vector<double> multipliers_;
};

} // namespace glossa::solvers
