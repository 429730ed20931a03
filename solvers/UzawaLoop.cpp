#include "solvers/UzawaLoop.hpp"

#include <cmath>

#include <Teuchos_CommHelpers.hpp>

#include "io/deck/ParameterSpec.hpp"

namespace glossa::solvers {

Teuchos::ParameterList incompressibilityParameters() {
  Teuchos::ParameterList p;
  io::declareString(p, "method", "augmented Lagrangian",
                    "augmented Lagrangian: Uzawa updates of an element multiplier until the "
                    "dilatation error is below the tolerance, with kappa_AL = penalty ratio x mu "
                    "in the tangent (the material's bulk modulus is then not used: the target "
                    "is theta = 1); penalty: one solve with the material's bulk modulus",
                    {"augmented Lagrangian", "penalty"});
  io::declareDouble(p, "penalty ratio", 100.0, "",
                    "kappa_AL / mu in augmented-Lagrangian mode (1e2-1e3 keeps the Krylov solve "
                    "cheap; see doc/incompressibility.md)", io::Range::closed(1.0, 1e9));
  io::declareDouble(p, "dilatation tolerance", 1e-3, "",
                    "augmented Lagrangian stops when max_e |theta_e - 1| is below this",
                    io::Range::open(0.0, 1.0));
  io::declareInt(p, "maximum Uzawa iterations", 50, "Newton solves per step before the step fails",
                 io::Range::closed(1, 10000));
  return p;
}

double UzawaLoop::tangentKappa(const Teuchos::ParameterList &s, double materialKappa, double mu) {
  return s.get<std::string>("method") == "augmented Lagrangian" ? s.get<double>("penalty ratio") * mu
                                                                : materialKappa;
}

UzawaLoop::UzawaLoop(const assembly::Assembler &assembler, const NewtonSolver &newton,
                     const Teuchos::ParameterList &s)
    : assembler_(assembler), newton_(newton),
      augmented_(s.get<std::string>("method") == "augmented Lagrangian"),
      tolerance_(s.get<double>("dilatation tolerance")), maxIterations_(s.get<int>("maximum Uzawa iterations")) {}

DilatationError UzawaLoop::dilatationError(const assembly::ElementFields &f) const {
  double local[2] = {0.0, 0.0}, volume = 0.0, maxErr = 0.0;
  for (std::size_t i = 0; i < f.theta.size(); ++i) {
    const double e = std::abs(f.theta[i] - 1.0);
    maxErr = std::max(maxErr, e);
    local[0] += e * f.referenceVolume[i];
    volume += f.referenceVolume[i];
  }
  local[1] = volume;
  double sums[2];
  DilatationError err;
  const auto &comm = *assembler_.comm();
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2, local, sums);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, maxErr, Teuchos::outArg(err.max));
  err.mean = sums[0] / sums[1];
  return err;
}

UzawaResult UzawaLoop::solve(assembly::Vector &u, std::vector<double> &lambda, double residualTolerance,
                             const NewtonSolver::IterationCallback &onNewton,
                             const std::function<void(int, const NewtonResult &, const DilatationError &)> &onUzawa) const {
  UzawaResult result;
  for (int k = 1; k <= (augmented_ ? maxIterations_ : 1); ++k) {
    NewtonResult n = newton_.solve(u, residualTolerance, onNewton);
    ++result.solves;
    result.newtonIterations += n.iterations;
    result.linearIterations += n.linearIterations;
    result.elementInverted = n.elementInverted;
    const bool newtonConverged = n.converged;
    result.newton.push_back(std::move(n));
    if (!newtonConverged) return result;

    const assembly::ElementFields fields = assembler_.elementFields(u, lambda);
    result.dilatation = dilatationError(fields);
    if (onUzawa) onUzawa(k, result.newton.back(), result.dilatation);
    if (!augmented_ || result.dilatation.max < tolerance_) {
      result.converged = true;
      return result;
    }
    // Lambda_e <- Lambda_e + U'(theta_e) (= Lambda_e + kappa_AL (theta_e - 1) to first order,
    // exactly for the quadratic U): the multiplier takes over the element pressure p_e, so the
    // next solve needs less volume change to carry it.
    for (std::size_t i = 0; i < lambda.size(); ++i) lambda[i] = fields.pressure[i];
  }
  return result;
}

} // namespace glossa::solvers
