#pragma once
// The sensitivity of the control points to the neural inputs at a converged step (issue 5,
// gradient controller): with f(u; alpha) = 0 the condensed residual,
//
//   d x_p / d u_M = -[K^{-1} (d f / d alpha_M) (d alpha_M / d u_M)]_p ,
//
// K the tangent at the converged state (NewtonSolver::solveTangent: one Krylov solve per muscle,
// one preconditioner for all), d f / d alpha_M by second-order finite differences of the
// assembled residual in the group's trial activation (the point laws and the external muscles
// re-solve their lambda_c at every evaluation, so no analytic alpha-derivative is needed), and
// d alpha / d u from the backward-Euler activation step (ActivationDynamics). The augmented
// Lagrange multipliers are held fixed: with the tangent's kappa_t = kappa kappa_AL / (kappa +
// kappa_AL) the volumetric response is that of kappa_t, a relative error of order mu / kappa_AL
// (1 % at the default kappa_AL = 100 mu) which the controller's full solves absorb.

#include <vector>

#include <Eigen/Core>

#include "assembly/Assembler.hpp"
#include "solvers/NewtonSolver.hpp"

namespace glossa::solvers {

struct ControlPointSensitivity {
  Eigen::MatrixXd dxdu; // 3 rows per point (x, y, z), one column per group
  int krylovIterations = 0;
};

// At the converged trial state (u, lambda) at `time`: the history has begun the step with the
// inputs whose sensitivity is wanted, and the solver's model has this time and lambda.
// Restores the groups' trial activations. Collective.
ControlPointSensitivity controlPointSensitivity(assembly::Assembler &assembler, const NewtonSolver &newton,
                                                const assembly::Vector &u, const std::vector<double> &lambda,
                                                double time, const std::vector<int> &groups,
                                                const std::vector<mesh::NodeId> &points);

} // namespace glossa::solvers
