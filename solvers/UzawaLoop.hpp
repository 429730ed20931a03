#pragma once
// The augmented-Lagrangian loop around each Newton solve (DESIGN.md §1, eq. 7):
//   solve f(u; Lambda) = 0, then Lambda_e <- Lambda_e + kappa_AL (theta_e - 1)
// until max_e |theta_e - 1| is below the tolerance. With a moderate kappa_AL in the tangent the
// Krylov solves stay cheap, while the multiplier carries the pressure that a pure penalty would
// need kappa/mu >= 1e6 to produce. In "penalty" mode the loop performs one solve.

#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "assembly/Assembler.hpp"
#include "solvers/NewtonSolver.hpp"

namespace glossa::solvers {

Teuchos::ParameterList incompressibilityParameters();

struct DilatationError {
  double max = 0.0;  // max over elements of |theta_e - 1|
  double mean = 0.0; // reference-volume-weighted mean of |theta_e - 1|
};

struct UzawaResult {
  bool converged = false;     // Newton converged and (AL mode) the dilatation tolerance was met
  bool elementInverted = false;
  int solves = 0;             // Newton solves = Uzawa iterations
  int newtonIterations = 0;
  int linearIterations = 0;
  DilatationError dilatation;
  std::vector<NewtonResult> newton;
};

class UzawaLoop {
public:
  UzawaLoop(const assembly::Assembler &assembler, const NewtonSolver &newton,
            const Teuchos::ParameterList &section);

  bool augmentedLagrangian() const { return augmented_; }
  // kappa in the tangent: kappa_AL in augmented-Lagrangian mode, the material's otherwise.
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
  double tolerance_;
  int maxIterations_;
};

} // namespace glossa::solvers
