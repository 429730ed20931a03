#pragma once
// The sensitivity of the control points to the neural inputs at a converged step (the gradient
// controller's, doc/control.md), from the model evaluator's derivatives: with f(x; p) = 0 the
// condensed residual, g(x) the control points' displacements (response g0) and p the inputs (p2),
//
//   dg/dp = -DgDx W^{-1} DfDp,
//
// W the tangent at the converged state (NewtonSolver::solveSensitivities: a Krylov solve per input,
// one preconditioner for all). DfDp comes from the model by finite differences in the groups'
// activations times d alpha / d u of the backward-Euler activation step (ActivationDynamics).
// W is the tangent of the model's volumetric laws and multipliers (p1) as they stand. With the
// inner solves' (kappa_t = kappa kappa_AL / (kappa + kappa_AL) at fixed multipliers) the volumetric
// response is that of kappa_t, off from the converged Uzawa loop's by order mu / kappa_AL (3 % on
// the tongue); the gradient controller therefore puts the constrained tangent's laws and
// multipliers in place first (ConstrainedTangent, ControlledSteps::keptSensitivity).

#include <vector>

#include <Eigen/Core>

#include "assembly/Assembler.hpp"
#include "solvers/nonlinear/NewtonSolver.hpp"

namespace glossa::solvers {

struct ControlPointSensitivity {
  Eigen::MatrixXd dxdu; // 3 rows per control point (x, y, z), one column per group asked
  int krylovIterations = 0;
  // du/du_M of every owned unknown, one column per group asked (the solves' solutions, of which
  // dxdu is the control points' rows): what other responses (the lumen) are linearised along.
  Teuchos::RCP<assembly::MultiVector> responses;
};

// At the converged trial state u: the solver's model has this step's time and multipliers, the
// muscle history has begun the step with the inputs whose sensitivity is wanted, and the model's
// response nodes are the control points. Columns for `groups` (muscle group indices). Collective.
ControlPointSensitivity controlPointSensitivity(const NewtonSolver &newton, const assembly::Vector &u,
                                                const std::vector<int> &groups);

} // namespace glossa::solvers
