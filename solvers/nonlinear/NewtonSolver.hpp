#pragma once
// One nonlinear solve f(u) = 0 with NOX (line-search Newton) on the Thyra model evaluator,
// configured from the deck's "Nonlinear solver" section. Reports the iterations, the Krylov
// iterations and the residual history (to show quadratic convergence).

#include <functional>
#include <string>
#include <vector>

#include "assembly/ModelEvaluator.hpp"
#include "solvers/nonlinear/SolveStatistics.hpp"
#include "solvers/parameters/NewtonParameters.hpp"

namespace NOX::Thyra {
class Group;
}
namespace Thyra {
template <class Scalar> class LinearOpWithSolveBase;
}

namespace glossa::solvers {

class NewtonSolver {
public:
  // `onIteration(k, ||f||, krylov iterations)` is called on every rank after each iteration.
  using IterationCallback = std::function<void(int, double, int)>;

  // `linearTolerance`: relative residual reduction asked of each Krylov solve. `keepLinearSolver`:
  // one NOX group (and so one Stratimikos solver with its preconditioner) serves every solve
  // until forgetLinearSolver(), so that a reused MueLu hierarchy lives across Uzawa iterations
  // (and load steps, if never forgotten). `directSolve`: the linear solver is MUMPS (a continued
  // solve then keeps its factors and asks its Krylov solves for `linearTolerance` at once).
  NewtonSolver(Teuchos::RCP<assembly::ModelEvaluator> model, const NewtonParameters &parameters,
               double lengthScale, double linearTolerance, bool keepLinearSolver = false, bool directSolve = false);

  // The absolute residual tolerance of a solve, from the norm of its initial residual (a caller
  // that scales the tolerance by the residual at the start needs no assembly of its own).
  using ToleranceRule = std::function<double(double initialResidualNorm)>;

  // Solves from the initial guess u (owned vector), overwriting it with the solution when
  // converged: the residual below `residualTolerance` (absolute; the caller scales it by the
  // load) and the update below the deck's update tolerance relative to the whole field.
  NewtonResult solve(assembly::Vector &u, double residualTolerance, const IterationCallback &onIteration) const;
  // `continuesLastSolve`: the same problem as the last solve (the Uzawa loop tightening an inexact
  // solve that met the volume, no multiplier moved), so a direct solve's kept factors still serve
  // as they would within one Newton solve ("reuse iterations"), instead of being refactored.
  NewtonResult solve(assembly::Vector &u, const ToleranceRule &residualTolerance, const IterationCallback &onIteration,
                     bool continuesLastSolve = false) const;
  // The Uzawa loop's inexact first solve: it stops on the residual test alone, and each Krylov
  // solve goes to at most `maximumForcing` relative (Eisenstat-Walker may ask less). Where it
  // stops the multipliers are updated, so that iterate must not depend on the linear solver:
  // with the forcing's usual 1e-2 an iterative solve on 2 ranks and a direct one on 1 stopped
  // 1.1e-5 apart in the answer (doc/incompressibility.md).
  NewtonResult solveToResidual(assembly::Vector &u, const ToleranceRule &residualTolerance,
                               const IterationCallback &onIteration, double maximumForcing) const;

  // Solves K(u) x_j = b_j for every column of `rhs` with the tangent at u (the model's time and
  // Lambda, the three-field bases condensed exactly at u), one preconditioner for all columns,
  // to the deck's linear tolerance: the sensitivities of a converged state (gradient control). Returns
  // the Krylov iterations; throws std::runtime_error if u is inadmissible or a solve fails.
  // `relativeTolerance` > 0 replaces the deck's linear tolerance (a caller that needs a few digits).
  int solveTangent(const assembly::Vector &u, const assembly::MultiVector &rhs, assembly::MultiVector &x,
                   double relativeTolerance = -1.0) const;
  // solveTangent for a controller's sensitivities (a right-hand side per muscle group), with the
  // linear solver setSensitivitySolver gave, else the Newton solves'.
  int solveSensitivities(const assembly::Vector &u, const assembly::MultiVector &rhs, assembly::MultiVector &x) const;
  // Linear solver/sensitivity solve chose MUMPS of their own: one fresh factorisation for all the
  // right-hand sides of a tangent, whatever Newton's solver keeps.
  void setSensitivitySolver(Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> factory) {
    sensitivitySolver_ = std::move(factory);
  }
  // The same for one right-hand side with the linear solver the Newton solves keep (MueLu reuse
  // scope = step or run), so its preconditioner is updated by the reuse rule rather than built
  // anew; without a kept solver, solveTangent.
  int solveTangentWithKeptSolver(const assembly::Vector &u, const assembly::Vector &rhs, assembly::Vector &x,
                                 double relativeTolerance) const;

  // Solves with the linear solver the last Newton solve left as it stands: its last assembled
  // tangent and its preconditioner (for a direct solve its factors), nothing assembled or
  // factored anew, to `relativeTolerance`. That tangent is the one at the solve's last iterate
  // but one or two, so this is for quantities that need a few digits near a converged state (the
  // airflow coupling's Jacobian, solvers/run/AirflowCoupling), at the cost of some back-
  // substitutions instead of an assembly and a factorisation. Returns the Krylov iterations;
  // throws std::runtime_error when no Newton solve has left a linear solver (none yet, or the
  // last one had converged before its first iteration) or the solve fails.
  int solveWithLastTangent(const assembly::MultiVector &rhs, assembly::MultiVector &x, double relativeTolerance) const;

  // The next solve builds its linear solver and preconditioner afresh (MueLu reuse scope = step:
  // called when a step solve starts, so a step's iterates do not depend on earlier steps' solves).
  void forgetLinearSolver() const { group_ = Teuchos::null; }

  double relativeResidualTolerance() const { return parameters_.residualTolerance; }
  // The model it solves: its nominal time and multipliers are those of the next solve.
  assembly::ModelEvaluator &model() const { return *model_; }

  // Steps the guarded full step has halved so far (Nonlinear solver/line search; summary.json's
  // newton_step_halvings): Newton steps that would have left an element inside out.
  int halvedSteps() const { return halvedSteps_; }
  bool guardsSteps() const { return parameters_.lineSearch == LineSearch::guardedFullStep; }

  // The Eisenstat-Walker forcing's first and largest value (the Krylov tolerance of a Newton
  // iteration far from the solution).
  static constexpr double kForcingCeiling = 1e-2;

private:
  // `updateTest`: the deck's (solve) or none (solveToResidual); `maximumForcing`: the
  // Eisenstat-Walker forcing's first and largest value; `continuesLastSolve` as for solve.
  NewtonResult run(assembly::Vector &u, const ToleranceRule &residualTolerance, const IterationCallback &onIteration,
                   bool updateTest, double maximumForcing, bool continuesLastSolve = false) const;
  // Solves lows x_j = b_j for every column to `relativeTolerance` (<= 0: the deck's linear
  // tolerance); `what` names the solve in the error it throws when it does not converge.
  int solveWith(Thyra::LinearOpWithSolveBase<double> &lows, const assembly::MultiVector &rhs, assembly::MultiVector &x,
                double relativeTolerance, const char *what) const;
  // The deck's update test as a forecast for the model, for the update from the last accepted iterate.
  assembly::ModelEvaluator::ConvergenceForecast updateForecast(double floor) const;

  Teuchos::RCP<assembly::ModelEvaluator> model_;
  NewtonParameters parameters_;
  double lengthScale_;
  double linearTolerance_;
  bool keepLinearSolver_;
  bool directSolve_;
  mutable Teuchos::RCP<NOX::Thyra::Group> group_; // kept between solves when keepLinearSolver_
  mutable Teuchos::RCP<NOX::Thyra::Group> lastGroup_; // the last solve's that iterated: its linear solver
  mutable int halvedSteps_ = 0;
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> sensitivitySolver_; // null: the model's
  int solveTangentWith(const Thyra::LinearOpWithSolveFactoryBase<double> &factory, const assembly::Vector &u,
                       const assembly::MultiVector &rhs, assembly::MultiVector &x, double relativeTolerance) const;
};

} // namespace glossa::solvers
