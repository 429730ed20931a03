#pragma once
// The Hill three-element muscle fibre (paper eq. 11-18, Martins et al. 1998): the fibre tension
//   T_f(lambda_f) = T_p(lambda_f) + T_s(lambda_f, lambda_c)            (eq. 11)
// with the series and contractile tensions equal, T_s = T_c (eq. 12), lambda_f = lambda_s
// lambda_c (eq. 13), and backward Euler for the contractile rate,
// d lambda_c/dt = (lambda_c - lambda_c_old) / dt.
// lambda_c is solved per call by a safeguarded bisection-Newton scalar solve; the tangent
// dT_f/dlambda_f is consistent (implicit differentiation of T_s = T_c). History dependent but
// pure: the caller owns lambda_c_old and decides whether to commit lambda_c.
//
// Cases (doc/materials.md):
//  - taut: T_c(lambda_c = lambda_f) > 0. The root lies in [lambda_lo, lambda_f) with
//    lambda_lo = lambda_f / stretchAtTension(1.01 T0max T0s alpha max f_cL max f_cV), a
//    guaranteed sign change.
//  - slack: T_c(lambda_c = lambda_f) = 0 (alpha T0s = 0, lambda_f outside f_cL's support, or the
//    fibre shortening faster than the contractile element can): T_s = 0, and
//    lambda_c = max(lambda_f, lambda_c_old - vmax dt) (the element shortens at most at its
//    maximum speed; with alpha T0s = 0 it follows the fibre: lambda_c = lambda_f).
//  - on a curve jump: T_s - T_c changes sign across a discontinuity of f_cL or f_cV without a
//    root (the bracket collapses onto the jump). The jump is read as a vertical segment of the
//    curve: lambda_c stays at the jump, T_s is the series tension there, and the tangent is that
//    of a locked contractile element, dT_s/dlambda_f at fixed lambda_c.

#include <limits>

#include "materials/BracketedNewtonSolver.hpp"
#include "materials/ContractileElement.hpp"
#include "materials/ParallelElement.hpp"
#include "materials/SeriesElement.hpp"

namespace glossa::materials {

enum class HillSolveStatus {
  Taut,            // converged, series element taut (T_s = T_c > 0)
  Slack,           // no contractile force at lambda_c = lambda_f: series element slack
  InvalidInput,    // lambda_f, lambda_c_old, dt not > 0 and finite, or alpha outside [0, 1]
  InvalidBracket,  // the guaranteed bracket failed (a curve exceeds its upper bound)
  NonFinite,       // a non-finite tension or slope during the solve
  MaxIterations,   // the scalar solve did not converge
  OnCurveJump,     // taut, lambda_c held at a jump of f_cL or f_cV (the paper set's curves are
                   // discontinuous at the ends of their domains): T_s lies within the jump
  SingularTangent  // d(T_s - T_c)/d lambda_c = 0 at the root: no consistent tangent
};
const char *describe(HillSolveStatus status);
inline bool succeeded(HillSolveStatus s) {
  return s == HillSolveStatus::Taut || s == HillSolveStatus::Slack || s == HillSolveStatus::OnCurveJump;
}

struct HillFibreInput {
  double lambdaF = 1.0;     // fibre stretch
  double alpha = 0.0;       // activation in [0, 1]
  double dt = 1.0;          // time step [s], > 0
  double lambdaCOld = 1.0;  // committed contractile stretch
  // Where the local solve for lambda_c starts (not finite: lambdaCOld): any start inside its
  // bracket finds the same root to the solve's tolerance.
  double lambdaCStart = std::numeric_limits<double>::quiet_NaN();
};

struct HillFibreResponse {
  double T = 0.0;             // T_f = T_p + T_s [Pa]
  double dTdLambdaF = 0.0;    // consistent tangent
  double Tp = 0.0;            // parallel tension
  double Ts = 0.0;            // series (= contractile) tension
  double lambdaC = 1.0;       // new contractile stretch (commit when the step converges)
  double lambdaCRate = 0.0;   // (lambdaC - lambdaCOld) / dt
  double storedEnergy = 0.0;  // psi_p(lambda_f) + psi_s(lambda_f; lambda_c) [J/m^3]
  // d lambda_c / d lambda_f of the taut solve's root (NaN otherwise): where a solve at a nearby
  // lambda_f in the same step may start.
  double dLambdaCdLambdaF = std::numeric_limits<double>::quiet_NaN();
  int iterations = 0;
  HillSolveStatus status = HillSolveStatus::InvalidInput;
};

class HillMuscleFibre {
 public:
  HillMuscleFibre(ParallelElement parallel, SeriesElement series, ContractileElement contractile,
                  ScalarSolveOptions solverOptions = defaultSolverOptions());
  // Table I elements (T0max = 668.8 kPa) with the given T0s and curve set.
  static HillMuscleFibre tableI(double T0s, ContractileCurves curves);
  // residualTolerance 1e-9 Pa (T0max ~ 1e5..1e6 Pa), xTolerance 1e-14.
  static ScalarSolveOptions defaultSolverOptions();
  // Below this series stretch at the largest contractile tension (alpha <~ 2e-11 with Table I)
  // the series element is taken as rigid: lambda_f / lambda_lo - 1 is then resolved to better
  // than 1 % (its round-off is ~2 ulp), so the bracket's 1 % margin holds above it.
  static constexpr double kRigidSeriesStretch = 1e4 * std::numeric_limits<double>::epsilon();

  HillFibreResponse evaluate(const HillFibreInput &in) const;

  const ParallelElement &parallel() const { return parallel_; }
  const SeriesElement &series() const { return series_; }
  const ContractileElement &contractile() const { return contractile_; }

 private:
  ParallelElement parallel_;
  SeriesElement series_;
  ContractileElement contractile_;
  BracketedNewtonSolver solver_;
};

}  // namespace glossa::materials
