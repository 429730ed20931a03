#pragma once
// The deck's Incompressibility section, declared and parsed once: the method (augmented
// Lagrangian with its Uzawa loop, penalty, mixed), kappa_AL and the loop's tolerances. Read by the
// Uzawa loop, the simulation and the mixed pressure state alike.

#include <Teuchos_ParameterList.hpp>

namespace glossa::solvers {

enum class IncompressibilityMethod { augmentedLagrangian, penalty, mixed };
// Anderson acceleration of the multiplier update: where the loop may not raise kappa_AL (under a
// controller: UzawaLoop::allowKappaRaises), always, or never.
enum class MultiplierAcceleration { automatic, anderson, none };

struct IncompressibilityParameters {
  IncompressibilityMethod method = IncompressibilityMethod::augmentedLagrangian;
  double penaltyRatio = 30.0;        // kappa_AL / mu
  double dilatationTolerance = 1e-3; // max_e |theta_e - theta_phys(p_e)|
  int maximumUzawaIterations = 50;
  bool inexactUzawa = true;          // Uzawa acceleration = inexact
  double innerTolerance = 1e-2;      // the inexact solve's relative residual
  double innerLinearTolerance = 1e-3; // at most, of each of its Krylov solves
  MultiplierAcceleration multiplierAcceleration = MultiplierAcceleration::automatic;
  int andersonDepth = 3;              // the pairs Anderson's update keeps
};

Teuchos::ParameterList incompressibilityParameters();
IncompressibilityParameters parseIncompressibilityParameters(const Teuchos::ParameterList &section);
// The deck's word for a method (summary.json, the log).
const char *methodName(IncompressibilityMethod method);

} // namespace glossa::solvers
