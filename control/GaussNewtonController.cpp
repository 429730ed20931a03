#include "control/GaussNewtonController.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "control/BoundedLeastSquares.hpp"
#include "control/RangeCheck.hpp"

namespace glossa::control {

std::string toString(GaussNewtonStop stop) {
  switch (stop) {
  case GaussNewtonStop::objectiveTolerance: return "objective tolerance";
  case GaussNewtonStop::stationary: return "stationary";
  case GaussNewtonStop::noDescent: return "no descent";
  case GaussNewtonStop::iterationLimit: return "iteration limit";
  case GaussNewtonStop::startFailed: return "start failed";
  case GaussNewtonStop::sensitivityFailed: return "sensitivity failed";
  }
  return "unknown";
}

void GaussNewtonParameters::validate(const std::string &prefix) const {
  const double inf = std::numeric_limits<double>::infinity();
  detail::requireInRange(prefix + "maxIterations", maxIterations, 1, inf);
  detail::requireInRange(prefix + "maxBacktracks", maxBacktracks, 0, inf);
  detail::requireInRange(prefix + "stepTolerance", stepTolerance, 0.0, 1.0, true);
  detail::requireInRange(prefix + "damping", damping, 0.0, inf, false, true);
  detail::requireInRange(prefix + "objectiveTolerance", objectiveTolerance, 0.0, inf, false, true);
}

GaussNewtonController::GaussNewtonController(const GaussNewtonParameters &parameters) : p_(parameters) {
  p_.validate();
}

GaussNewtonResult GaussNewtonController::minimise(const Eigen::VectorXd &start, const Evaluator &evaluate,
                                                  const Sensitivity &sensitivity) const {
  GaussNewtonResult out;
  const Eigen::Index n = start.size();
  Eigen::VectorXd u = start.cwiseMax(0.0).cwiseMin(1.0);
  ControlEvaluation e = evaluate(u);
  ++out.evaluations;
  out.inputs = u;
  if (!e.ok) {
    out.stop = GaussNewtonStop::startFailed;
    out.objective = std::numeric_limits<double>::infinity();
    return out;
  }
  out.objective = e.objective;
  for (int k = 0;; ++k) {
    if (e.objective <= p_.objectiveTolerance) {
      out.stop = GaussNewtonStop::objectiveTolerance;
      return out;
    }
    if (k == p_.maxIterations || n == 0) {
      out.stop = n == 0 ? GaussNewtonStop::stationary : GaussNewtonStop::iterationLimit;
      return out;
    }
    const Eigen::MatrixXd S = sensitivity(u);
    ++out.sensitivities;
    if (S.size() == 0) {
      out.stop = GaussNewtonStop::sensitivityFailed;
      return out;
    }
    if (S.rows() != e.residual.size() || S.cols() != n)
      throw std::runtime_error("Gauss-Newton controller: the sensitivity is " + std::to_string(S.rows()) + " x " +
                               std::to_string(S.cols()) + ", expected " + std::to_string(e.residual.size()) + " x " +
                               std::to_string(n));
    const double diagonal = n > 0 ? (S.transpose() * S).diagonal().maxCoeff() : 0.0;
    const double rho = p_.damping * diagonal + std::numeric_limits<double>::min();
    const Eigen::VectorXd du =
        solveBoundedLeastSquares(S, -e.residual, -u, Eigen::VectorXd::Ones(n) - u, rho).x;
    if (du.cwiseAbs().maxCoeff() < p_.stepTolerance) {
      out.stop = GaussNewtonStop::stationary;
      return out;
    }
    bool accepted = false;
    double t = 1.0;
    for (int b = 0; b <= p_.maxBacktracks && !accepted; ++b, t *= 0.5) {
      const Eigen::VectorXd trial = (u + t * du).cwiseMax(0.0).cwiseMin(1.0);
      const ControlEvaluation et = evaluate(trial);
      ++out.evaluations;
      if (et.ok && et.residual.squaredNorm() < e.residual.squaredNorm()) {
        u = trial;
        e = et;
        accepted = true;
      }
    }
    if (!accepted) {
      out.stop = GaussNewtonStop::noDescent;
      return out;
    }
    ++out.iterations;
    out.inputs = u;
    out.objective = e.objective;
  }
}

}  // namespace glossa::control
