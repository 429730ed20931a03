#include "materials/HillMuscleFibre.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace glossa::materials {

const char *describe(HillSolveStatus status) {
  switch (status) {
    case HillSolveStatus::Taut:
      return "converged (series element taut)";
    case HillSolveStatus::Slack:
      return "series element slack";
    case HillSolveStatus::InvalidInput:
      return "invalid input (lambda_f, lambda_c_old, dt must be > 0, alpha in [0, 1])";
    case HillSolveStatus::InvalidBracket:
      return "no sign change of T_s - T_c on the guaranteed bracket";
    case HillSolveStatus::NonFinite:
      return "non-finite tension during the lambda_c solve";
    case HillSolveStatus::MaxIterations:
      return "lambda_c solve reached its iteration limit";
    case HillSolveStatus::OnCurveJump:
      return "converged onto a jump of f_cL or f_cV (contractile element held)";
    case HillSolveStatus::SingularTangent:
      return "d(T_s - T_c)/d lambda_c = 0 at the root";
  }
  return "?";
}

HillMuscleFibre::HillMuscleFibre(ParallelElement parallel, SeriesElement series,
                                 ContractileElement contractile, ScalarSolveOptions solverOptions)
    : parallel_(std::move(parallel)),
      series_(std::move(series)),
      contractile_(std::move(contractile)),
      solver_(solverOptions) {}

HillMuscleFibre HillMuscleFibre::tableI(double T0s, ContractileCurves curves) {
  const double T0max = ParallelElement::kTableIT0max;
  return {ParallelElement::tableI(), SeriesElement::tableI(T0max),
          ContractileElement(T0max, T0s, std::move(curves))};
}

ScalarSolveOptions HillMuscleFibre::defaultSolverOptions() {
  ScalarSolveOptions o;
  o.xTolerance = 1e-14;
  o.residualTolerance = 1e-9;
  o.maxIterations = 200;
  return o;
}

HillFibreResponse HillMuscleFibre::evaluate(const HillFibreInput &in) const {
  HillFibreResponse r;
  const bool valid = std::isfinite(in.lambdaF) && in.lambdaF > 0.0 && std::isfinite(in.lambdaCOld) &&
                     in.lambdaCOld > 0.0 && std::isfinite(in.dt) && in.dt > 0.0 && in.alpha >= 0.0 &&
                     in.alpha <= 1.0;
  if (!valid) return r;  // status InvalidInput

  const FibreTension p = parallel_.evaluate(in.lambdaF);
  r.Tp = p.T;
  r.storedEnergy = p.energy;
  auto finish = [&](double lambdaC, const SeriesTension &s, double dTsdLambdaF, HillSolveStatus status) {
    r.lambdaC = lambdaC;
    r.lambdaCRate = (lambdaC - in.lambdaCOld) / in.dt;
    r.Ts = s.T;
    r.T = p.T + s.T;
    r.dTdLambdaF = p.dTdLambda + dTsdLambdaF;
    r.storedEnergy += s.energy;
    r.status = status;
    return r;
  };

  // Slack: the contractile element can carry no force with the series element at rest length.
  const ContractileTension atFibre =
      contractile_.evaluate(in.lambdaF, (in.lambdaF - in.lambdaCOld) / in.dt, in.alpha);
  if (!(atFibre.T > 0.0)) {
    const double lambdaC =
        in.alpha * contractile_.T0s() == 0.0
            ? in.lambdaF
            : std::max(in.lambdaF, in.lambdaCOld - contractile_.maxShorteningRate() * in.dt);
    return finish(lambdaC, SeriesTension{}, 0.0, HillSolveStatus::Slack);
  }

  // Taut: R(lambda_c) = T_s(lambda_f, lambda_c) - T_c(lambda_c, (lambda_c - lambda_c_old)/dt) = 0.
  // R(lambda_f) = -T_c < 0; R(lambda_lo) >= T0max T0s alpha max(f_cL f_cV) - T_c >= 0.
  // (1 % margin on the bound against round-off in T_s(lambda_lo).)
  const double tensionBound = 1.01 * contractile_.T0max() * in.alpha * contractile_.capacityBound();
  const double lambdaSBound = series_.stretchAtTension(tensionBound);
  // Vanishing activation (alpha ~ 1e-16 a step after a neural input starts from 0): the series
  // stretch at the largest contractile tension is then within round-off of 1, lambda_lo rounds
  // onto lambda_f (or lambda_f / lambda_lo - 1 is too coarse for the 1 % margin) and the bracket
  // is lost. Below kRigidSeriesStretch the series element is rigid beside the contractile
  // element: lambda_c = lambda_f, T_s = T_c(lambda_f), dT_s/dlambda_f = dT_c/dlambda_c +
  // (1/dt) dT_c/drate, the limit of the taut branch (errors of order kRigidSeriesStretch
  // relative to T_c), which tends to the passive response as alpha -> 0.
  if (lambdaSBound - 1.0 < kRigidSeriesStretch) {
    const SeriesTension rigid{atFibre.T, 0.0, 0.0, 0.0};  // psi_s ~ T_s^2 / (2 T0max c1 c2) ~ 0
    return finish(in.lambdaF, rigid, atFibre.dLambdaC + atFibre.dRate / in.dt, HillSolveStatus::Taut);
  }
  const double lo = in.lambdaF / lambdaSBound;
  auto residual = [&](double lambdaC) {
    const SeriesTension s = series_.evaluate(in.lambdaF, lambdaC);
    const ContractileTension c = contractile_.evaluate(lambdaC, (lambdaC - in.lambdaCOld) / in.dt, in.alpha);
    return ValueSlope{s.T - c.T, s.dLambdaC - c.dLambdaC - c.dRate / in.dt};
  };
  const ScalarSolveResult root =
      solver_.solve(residual, lo, in.lambdaF, std::isfinite(in.lambdaCStart) ? in.lambdaCStart : in.lambdaCOld);
  r.iterations = root.iterations;
  switch (root.status) {
    case ScalarSolveStatus::Converged:
      break;
    case ScalarSolveStatus::ResidualNotReduced: {  // a jump of f_cL or f_cV: contractile element held
      const SeriesTension s = series_.evaluate(in.lambdaF, root.x);
      return finish(root.x, s, s.dLambdaF, HillSolveStatus::OnCurveJump);
    }
    case ScalarSolveStatus::InvalidBracket:
      r.status = HillSolveStatus::InvalidBracket;
      return r;
    case ScalarSolveStatus::NonFinite:
      r.status = HillSolveStatus::NonFinite;
      return r;
    case ScalarSolveStatus::MaxIterations:
      r.status = HillSolveStatus::MaxIterations;
      return r;
  }

  // Implicit differentiation: dlambda_c/dlambda_f = -(dT_s/dlambda_f) / R'(lambda_c), so
  // dT_s/dlambda_f (total) = a + b dlambda_c/dlambda_f = a (R' - b) / R' with a = dT_s/dlambda_f,
  // b = dT_s/dlambda_c (series and contractile stiffness in series).
  const SeriesTension s = series_.evaluate(in.lambdaF, root.x);
  const double dR = root.slope;
  if (!(std::abs(dR) > 1e-12 * (std::abs(s.dLambdaC) + std::abs(dR - s.dLambdaC)))) {
    r.status = HillSolveStatus::SingularTangent;
    return r;
  }
  const double dTs = s.dLambdaF * (dR - s.dLambdaC) / dR;
  r.dLambdaCdLambdaF = -s.dLambdaF / dR;
  return finish(root.x, s, dTs, HillSolveStatus::Taut);
}

}  // namespace glossa::materials
