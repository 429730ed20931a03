#pragma once
// The bounded, damped linear least-squares problem of one Gauss-Newton iteration of the gradient
// controller (GaussNewtonController.hpp):
//
//   minimise  |A x - b|^2 + rho |x|^2   subject to  lower <= x <= upper,
//
// solved exactly by a primal active-set method (Lawson & Hanson's NNLS extended to two-sided
// bounds, as in Stark & Parker's BVLS): variables at a bound stay fixed while the free ones
// solve the unconstrained problem; a variable is freed when the gradient points into the box and
// fixed when a step would leave it. rho > 0 makes every sub-problem strictly convex, so a muscle
// whose activation moves no control point (a zero column of A) gets x = 0 clipped to the box
// instead of an arbitrary value. Meant for the few muscle groups of a control step (n <= ~50).

#include <Eigen/Core>

namespace glossa::control {

struct BoundedLeastSquaresResult {
  Eigen::VectorXd x;
  int iterations = 0;  // active-set changes
  bool converged = false;  // KKT conditions met within the iteration limit
};

// Throws std::invalid_argument if the sizes disagree, lower > upper somewhere, the bounds are not
// finite or rho < 0. With rho = 0 and A rank-deficient the minimiser is not unique; the result is
// then one of them.
BoundedLeastSquaresResult solveBoundedLeastSquares(const Eigen::MatrixXd &A, const Eigen::VectorXd &b,
                                                   const Eigen::VectorXd &lower, const Eigen::VectorXd &upper,
                                                   double rho = 0.0);

}  // namespace glossa::control
