#pragma once
// The relative tolerance of each Krylov solve inside a Newton solve (the forcing term eta_k of an
// inexact Newton method: ||f_k + K_k dx_k|| <= eta_k ||f_k||), Eisenstat-Walker choice 2 with
// NOX's constants and safeguard, plus the safeguard against over-solving of Kelley (Iterative
// Methods for Linear and Nonlinear Equations, SIAM 1995, section 6.3):
//   eta_k = gamma (||f_k|| / ||f_(k-1)||)^alpha, gamma = 0.9, alpha = 1.5;
//   if gamma eta_(k-1)^alpha > 0.1: eta_k >= gamma eta_(k-1)^alpha (a sudden drop is not trusted);
//   eta_k >= 0.5 tau / ||f_k||   (no more than the residual test tau still asks for);
//   eta_min <= eta_k <= eta_max, eta_0 = eta_max.
// Without the last bound the final Newton iteration of a solve, whose residual needs one more
// digit or two to pass its test, asked the full linear tolerance (1e-6) of a quadratic forecast
// that lies far below the test: 14 of a load step's 47 Krylov iterations on the step-44 block,
// the largest of its five solves (doc/incompressibility.md).
//
// No Trilinos: NewtonSolver hands its result to NOX for the next linear solve.

namespace glossa::solvers {

class InexactNewtonForcing {
public:
  // eta_min: the deck's linear tolerance; eta_max: the first and largest value; tau: the solve's
  // absolute residual tolerance (0: no over-solving bound).
  InexactNewtonForcing(double minimum, double maximum, double residualTolerance);

  // The tolerance of the first linear solve of a Newton solve.
  double first();
  // The tolerance of the next linear solve, at the iterate whose residual norm is `residual`, the
  // iterate before having had `previousResidual`.
  double next(double residual, double previousResidual);

  static constexpr double kGamma = 0.9, kAlpha = 1.5;

private:
  double minimum_, maximum_, residualTolerance_;
  double last_ = 0.0;
};

} // namespace glossa::solvers
