#include "solvers/nonlinear/NewtonSolver.hpp"

#include <NOX.H>
#include <NOX_Thyra.H>

#include <NOX_Observer.hpp>
#include <NOX_SolverStats.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <algorithm>
#include <cmath>

#include "assembly/TimeSplit.hpp"
#include "solvers/linear/LinearSolveFailure.hpp"
#include "solvers/linear/MumpsPreconditioner.hpp"
#include "solvers/nonlinear/GuardedFullStep.hpp"
#include "solvers/nonlinear/InexactNewtonForcing.hpp"

namespace glossa::solvers {

using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;

namespace {
// The guarded full step's shortest step, 2^-4 of Newton's: a direction that still inverts an
// element at a sixteenth of its length is left to the load step's cut-back (GuardedFullStep.hpp).
constexpr int kGuardedHalvings = 4;

class IterationObserver : public NOX::Observer {
public:
  // `forcing` (null: NOX's own): sets each iteration's linear tolerance in `linearSolver`.
  IterationObserver(const NewtonSolver::IterationCallback &cb, NewtonResult &r, assembly::ModelEvaluator &model,
                    InexactNewtonForcing *forcing, ParameterList &linearSolver)
      : cb_(cb), r_(r), model_(model), forcing_(forcing), linearSolver_(linearSolver) {}
  void runPreIterate(const NOX::Solver::Generic &solver) override {
    if (forcing_ == nullptr || solver.getNumIterations() == 0) return;
    linearSolver_.set("Tolerance", forcing_->next(solver.getSolutionGroup().getNormF(),
                                                  solver.getPreviousSolutionGroup().getNormF()));
  }
  void runPostIterate(const NOX::Solver::Generic &solver) override {
    // The accepted iterate becomes the base of the next three-field linearisation.
    const auto &x = dynamic_cast<const NOX::Thyra::Vector &>(solver.getSolutionGroup().getX());
    model_.advanceIterates(*model_.displacementOf(x.getThyraVector()));
    const double normF = solver.getSolutionGroup().getNormF();
    const int krylov = solver.getSolverStatistics()->linearSolve.lastLinearSolve_NumIterations;
    r_.residualNorms.push_back(normF);
    r_.linearIterationsPerStep.push_back(krylov);
    if (cb_) cb_(solver.getNumIterations(), normF, krylov);
  }

private:
  const NewtonSolver::IterationCallback &cb_;
  NewtonResult &r_;
  assembly::ModelEvaluator &model_;
  InexactNewtonForcing *forcing_;
  ParameterList &linearSolver_;
};

// ||f|| <= max(tolerance, floor): the floor is what round-off leaves of a residual assembled from
// element terms of size forceScale (AssemblyStatus, from the last assembly), kRoundOffFactor
// machine epsilons of it (the observed floor is 1-2 epsilons of it). Without it a load that is tiny against the stiffness
// (bone under gravity, the first steps of a ramp) asks for a residual below round-off and every
// step is cut back to nothing.
class NormFAboveRoundOff : public NOX::StatusTest::Generic {
public:
  static constexpr double kRoundOffFactor = 10.0;
  NormFAboveRoundOff(double tolerance, const assembly::ModelEvaluator &model) : tolerance_(tolerance), model_(model) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic &problem, NOX::StatusTest::CheckType) override {
    normF_ = problem.getSolutionGroup().getNormF();
    floor_ = kRoundOffFactor * std::numeric_limits<double>::epsilon() * model_.lastStatus().forceScale;
    status_ = normF_ <= std::max(tolerance_, floor_) ? NOX::StatusTest::Converged : NOX::StatusTest::Unconverged;
    return status_;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream &print(std::ostream &stream, int indent) const override {
    for (int i = 0; i < indent; ++i) stream << ' ';
    return stream << status_ << "||F|| = " << normF_ << " <= max(" << tolerance_ << ", round-off floor " << floor_
                  << ")\n";
  }

private:
  double tolerance_;
  const assembly::ModelEvaluator &model_;
  double normF_ = 0.0, floor_ = 0.0;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};
// ||x_k - x_(k-1)||_2 <= tolerance ||x_k||_2 + floor sqrt(N): the Newton update relative to the
// whole field. NOX's weighted RMS norm weighs every component by its own size, so the unknowns
// that hardly move (beside symmetry planes and supports) decided it and asked for one or two
// Newton iterations per solve beyond the residual test (doc/incompressibility.md).
double relativeUpdateBound(double tolerance, double floor, double xNorm, double length) {
  return tolerance * xNorm + floor * std::sqrt(length);
}

class RelativeUpdate : public NOX::StatusTest::Generic {
public:
  RelativeUpdate(double tolerance, double floor) : tolerance_(tolerance), floor_(floor) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic &problem, NOX::StatusTest::CheckType) override {
    if (problem.getNumIterations() == 0) return status_ = NOX::StatusTest::Unconverged;
    const NOX::Abstract::Vector &x = problem.getSolutionGroup().getX();
    const RCP<NOX::Abstract::Vector> step = x.clone(NOX::DeepCopy);
    step->update(-1.0, problem.getPreviousSolutionGroup().getX(), 1.0);
    update_ = step->norm();
    bound_ = relativeUpdateBound(tolerance_, floor_, x.norm(), static_cast<double>(x.length()));
    status_ = update_ <= bound_ ? NOX::StatusTest::Converged : NOX::StatusTest::Unconverged;
    return status_;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream &print(std::ostream &stream, int indent = 0) const override {
    for (int i = 0; i < indent; ++i) stream << ' ';
    return stream << status_ << "||dx|| = " << update_ << " <= " << bound_ << "\n";
  }

private:
  double tolerance_, floor_;
  double update_ = 0.0, bound_ = 0.0;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};
} // namespace

NewtonSolver::NewtonSolver(RCP<assembly::ModelEvaluator> model, const NewtonParameters &parameters, double lengthScale,
                           double linearTolerance, bool keepLinearSolver, bool directSolve)
    : model_(std::move(model)), parameters_(parameters), lengthScale_(lengthScale), linearTolerance_(linearTolerance),
      keepLinearSolver_(keepLinearSolver), directSolve_(directSolve) {}

NewtonResult NewtonSolver::solve(assembly::Vector &u, double residualTolerance,
                                 const IterationCallback &onIteration) const {
  return solve(u, [residualTolerance](double) { return residualTolerance; }, onIteration);
}

NewtonResult NewtonSolver::solve(assembly::Vector &u, const ToleranceRule &toleranceRule,
                                 const IterationCallback &onIteration, bool continuesLastSolve) const {
  // A continued direct solve starts near its solution, with factors of an earlier tangent: the
  // forcing's loose first tolerance would leave its first Newton step inexact (on the §7.1 (b) and
  // (c) blocks 282 and 303 Newton iterations against 234 and 243), so it asks the deck's. An
  // iterative one keeps the forcing: its preconditioner is what it would have been anyway.
  return run(u, toleranceRule, onIteration, /*updateTest=*/true,
             continuesLastSolve && directSolve_ ? linearTolerance_ : kForcingCeiling, continuesLastSolve);
}

NewtonResult NewtonSolver::solveToResidual(assembly::Vector &u, const ToleranceRule &toleranceRule,
                                           const IterationCallback &onIteration, double maximumForcing) const {
  return run(u, toleranceRule, onIteration, /*updateTest=*/false, std::min(maximumForcing, kForcingCeiling));
}

NewtonResult NewtonSolver::run(assembly::Vector &u, const ToleranceRule &toleranceRule,
                               const IterationCallback &onIteration, bool updateTest, double maximumForcing,
                               bool continuesLastSolve) const {
  using namespace NOX::StatusTest;
  NewtonResult result;
  result.continuesLastSolve = continuesLastSolve;

  model_->resetIterates(u);
  // A continued solve is the last one's problem from its last iterate: its factors were kept for
  // a tangent no farther away than within one solve.
  if (!continuesLastSolve) MumpsPreconditionerFactory::beginNewtonSolve();
  NOX::Thyra::Vector initialGuess(model_->initialGuess(u));
  RCP<NOX::Thyra::Group> group;
  if (keepLinearSolver_ && !group_.is_null()) {
    // setX invalidates F and the Jacobian but keeps the linear solver object and with it the
    // preconditioner, which MueLu then updates according to its "reuse: type".
    group = group_;
    group->setX(initialGuess);
  } else {
    group = rcp(new NOX::Thyra::Group(initialGuess, model_, model_->create_W_op(), model_->get_W_factory(),
                                      Teuchos::null, Teuchos::null, Teuchos::null));
    if (keepLinearSolver_) group_ = group;
  }
  group->computeF();
  const double normF0 = group->getNormF();
  result.residualNorms.push_back(normF0);
  const double residualTolerance = toleranceRule(normF0);

  auto normF = rcp(new NormFAboveRoundOff(residualTolerance, *model_));
  // The deck's update test, relative to the whole field (none in solveToResidual).
  const double updateFloor = 1e-9 * lengthScale_;
  auto converged = rcp(new Combo(Combo::AND));
  converged->addStatusTest(normF);
  if (updateTest) converged->addStatusTest(rcp(new RelativeUpdate(parameters_.updateTolerance, updateFloor)));
  auto tests = rcp(new Combo(Combo::OR));
  tests->addStatusTest(rcp(new FiniteValue));
  tests->addStatusTest(converged);
  tests->addStatusTest(rcp(new MaxIters(parameters_.maximumIterations)));

  auto params = Teuchos::parameterList();
  params->set("Nonlinear Solver", "Line Search Based");
  const LineSearch ls = parameters_.lineSearch;
  ParameterList &lineSearch = params->sublist("Line Search");
  if (ls == LineSearch::guardedFullStep) {
    lineSearch.set("Method", "User Defined");
    lineSearch.set<RCP<NOX::LineSearch::UserDefinedFactory>>(
        "User Defined Line Search Factory", rcp(new GuardedFullStepFactory(kGuardedHalvings, halvedSteps_)));
  } else {
    lineSearch.set("Method", ls == LineSearch::fullStep    ? "Full Step"
                             : ls == LineSearch::backtrack ? "Backtrack"
                                                           : "Polynomial");
  }
  params->sublist("Printing").set("Output Information", NOX::Utils::Error);
  // NOX passes its own relative tolerance to every linear solve: the deck's (constant), NOX's
  // Eisenstat-Walker "Type 1", or "Type 2" with the over-solving bound (InexactNewtonForcing), which the
  // observer sets before each iteration while NOX keeps the value it is given ("Constant").
  auto &newtonParams = params->sublist("Direction").sublist("Newton");
  ParameterList &linearSolverParams = newtonParams.sublist("Linear Solver");
  linearSolverParams.set("Tolerance", linearTolerance_);
  InexactNewtonForcing forcing(linearTolerance_, maximumForcing, residualTolerance);
  if (parameters_.forcing == ForcingTerm::type1) {
    newtonParams.set("Forcing Term Method", "Type 1");
    newtonParams.set("Forcing Term Minimum Tolerance", linearTolerance_);
    newtonParams.set("Forcing Term Initial Tolerance", maximumForcing);
    newtonParams.set("Forcing Term Maximum Tolerance", maximumForcing);
  } else if (parameters_.forcing == ForcingTerm::type2) {
    linearSolverParams.set("Tolerance", forcing.first());
  }
  params->sublist("Solver Options")
      .set<RCP<NOX::Observer>>("User Defined Pre/Post Operator",
                               rcp(new IterationObserver(onIteration, result, *model_,
                                                         parameters_.forcing == ForcingTerm::type2 ? &forcing : nullptr,
                                                         linearSolverParams)));

  // Already converged (e.g. an Uzawa update that changed nothing)? Then no iteration is needed.
  if (std::isfinite(normF0) && normF0 <= residualTolerance) {
    result.converged = true;
    return result;
  }
  if (!std::isfinite(normF0)) {
    result.elementInverted = !model_->lastStatus().valid;
    return result;
  }

  auto solver = NOX::Solver::buildSolver(group, tests, params);
  lastGroup_ = group;
  // The model skips the tangent where the update test is about to pass (ModelEvaluator::
  // setConvergenceForecast), with the test's own formula; cleared when the solve ends. Without
  // an update test nothing forecasts the residual's: every pass assembles the tangent.
  if (updateTest) model_->setConvergenceForecast(updateForecast(updateFloor));
  struct ClearForecast {
    assembly::ModelEvaluator &model;
    ~ClearForecast() { model.setConvergenceForecast({}); }
  } clearForecast{*model_};
  StatusType status = Failed;
  try {
    status = solver->solve();
  } catch (const std::exception &e) {
    // A Krylov breakdown (e.g. CG meeting an indefinite tangent far from equilibrium) fails
    // this solve, not the run: the time stepper cuts back.
    result.failure = "linear solve failed: " + linearSolveFailure(e.what());
    result.iterations = solver->getNumIterations();
    result.elementInverted = !model_->lastStatus().valid;
    return result;
  }
  result.iterations = solver->getNumIterations();
  result.linearIterations = solver->getSolverStatistics()->linearSolve.lastNonlinearSolve_NumLinearIterations;
  result.converged = status == Converged;
  result.elementInverted = !model_->lastStatus().valid;
  if (result.converged) {
    const auto &x = dynamic_cast<const NOX::Thyra::Vector &>(solver->getSolutionGroup().getX());
    model_->acceptSolution(x.getThyraVector(), u);
  }
  return result;
}

assembly::ModelEvaluator::ConvergenceForecast NewtonSolver::updateForecast(double floor) const {
  const double tolerance = parameters_.updateTolerance;
  return [tolerance, floor](const assembly::Vector &dx, const assembly::Vector &x) {
    return dx.norm2() <= relativeUpdateBound(tolerance, floor, x.norm2(), static_cast<double>(x.getGlobalLength()));
  };
}

int NewtonSolver::solveTangentWithKeptSolver(const assembly::Vector &u, const assembly::Vector &rhs, assembly::Vector &x,
                                             double relativeTolerance) const {
  if (!keepLinearSolver_ || group_.is_null()) {
    assembly::MultiVector b(rhs.getMap(), 1), solution(rhs.getMap(), 1);
    b.getVectorNonConst(0)->assign(rhs);
    const int iterations = solveTangent(u, b, solution, relativeTolerance);
    x.assign(*solution.getVector(0));
    return iterations;
  }
  model_->resetIterates(u);
  group_->setX(NOX::Thyra::Vector(model_->initialGuess(u)));
  if (group_->computeJacobian() != NOX::Abstract::Group::Ok || !model_->lastStatus().valid)
    throw std::runtime_error("tangent solve: an element is inverted at the state");
  const auto space = model_->get_x_space();
  auto b = rcp(new assembly::Vector(rhs, Teuchos::Copy));
  x.putScalar(0.0);
  const NOX::Thyra::Vector in(Thyra::createVector(RCP<assembly::Vector>(b), space));
  NOX::Thyra::Vector out(Thyra::createVector(Teuchos::rcpFromRef(x), space));
  ParameterList p;
  p.set("Tolerance", relativeTolerance);
  if (group_->applyJacobianInverse(p, in, out) != NOX::Abstract::Group::Ok)
    throw std::runtime_error("tangent solve did not converge");
  if (p.isSublist("Output") && p.sublist("Output").isType<int>("Number of Linear Iterations"))
    return p.sublist("Output").get<int>("Number of Linear Iterations");
  return 0;
}

int NewtonSolver::solveWith(Thyra::LinearOpWithSolveBase<double> &lows, const assembly::MultiVector &rhs,
                           assembly::MultiVector &x, double relativeTolerance, const char *what) const {
  const auto space = model_->get_x_space();
  const auto B = Thyra::createConstMultiVector<double, assembly::LO, assembly::GO, assembly::Node>(
      Teuchos::rcpFromRef(rhs), space);
  x.putScalar(0.0);
  const auto X = Thyra::createMultiVector<double, assembly::LO, assembly::GO, assembly::Node>(Teuchos::rcpFromRef(x), space);
  Thyra::SolveCriteria<double> criteria;
  criteria.solveMeasureType =
      Thyra::SolveMeasureType(Thyra::SOLVE_MEASURE_NORM_RESIDUAL, Thyra::SOLVE_MEASURE_NORM_RHS);
  criteria.requestedTol = relativeTolerance > 0.0 ? relativeTolerance : linearTolerance_;
  const auto status = lows.solve(Thyra::NOTRANS, *B, X.ptr(), Teuchos::ptrFromRef(criteria));
  if (status.solveStatus == Thyra::SOLVE_STATUS_UNCONVERGED)
    throw std::runtime_error(std::string(what) + " did not converge: " + status.message);
  int iterations = 0;
  if (!status.extraParameters.is_null() && status.extraParameters->isParameter("Iteration Count"))
    iterations = status.extraParameters->get<int>("Iteration Count");
  return iterations;
}

int NewtonSolver::solveWithLastTangent(const assembly::MultiVector &rhs, assembly::MultiVector &x,
                                       double relativeTolerance) const {
  const RCP<Thyra::LinearOpWithSolveBase<double>> lows =
      lastGroup_.is_null() ? Teuchos::null : lastGroup_->getNonconstJacobian();
  if (lows.is_null() || lows->range().is_null()) throw std::runtime_error("no Newton solve has left a linear solver");
  return solveWith(*lows, rhs, x, relativeTolerance, "the solve with the last tangent");
}

int NewtonSolver::solveTangent(const assembly::Vector &u, const assembly::MultiVector &rhs,
                               assembly::MultiVector &x, double relativeTolerance) const {
  return solveTangentWith(*model_->get_W_factory(), u, rhs, x, relativeTolerance);
}

int NewtonSolver::solveSensitivities(const assembly::Vector &u, const assembly::MultiVector &rhs,
                                     assembly::MultiVector &x) const {
  return solveTangentWith(sensitivitySolver_.is_null() ? *model_->get_W_factory() : *sensitivitySolver_, u, rhs, x, -1.0);
}

int NewtonSolver::solveTangentWith(const Thyra::LinearOpWithSolveFactoryBase<double> &factory, const assembly::Vector &u,
                                   const assembly::MultiVector &rhs, assembly::MultiVector &x,
                                   double relativeTolerance) const {
  TEUCHOS_TEST_FOR_EXCEPTION(!model_->mixedPressure().is_null(), std::logic_error,
                             "tangent solves are of the condensed tangent; the mixed method has none");
  model_->resetIterates(u);
  RCP<Thyra::LinearOpWithSolveBase<double>> lows;
  {
    const assembly::PartTimer timer(assembly::TimedPart::tangentSetup);
    auto in = model_->createInArgs();
    auto uCopy = rcp(new assembly::Vector(u, Teuchos::Copy));
    in.set_x(Thyra::createVector(RCP<assembly::Vector>(uCopy), model_->get_x_space()));
    auto out = model_->createOutArgs();
    const RCP<Thyra::LinearOpBase<double>> W = model_->create_W_op();
    out.set_W_op(W);
    model_->evalModel(in, out);
    if (!model_->lastStatus().valid) throw std::runtime_error("tangent solve: an element is inverted at the state");
    lows = Thyra::linearOpWithSolve<double>(factory, W);
  }
  const assembly::PartTimer timer(assembly::TimedPart::tangentSolve);
  return solveWith(*lows, rhs, x, relativeTolerance, "tangent solve");
}

} // namespace glossa::solvers
