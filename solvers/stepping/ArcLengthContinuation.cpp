#include "solvers/stepping/ArcLengthContinuation.hpp"

#include <algorithm>
#include <cmath>

#include <Teuchos_oblackholestream.hpp>

#include <LOCA.H>
#include <LOCA_MultiContinuation_ExtendedVector.H>
#include <LOCA_StatusTest_Abstract.H>
#include <LOCA_Thyra.H>
#include <NOX_Observer.hpp>
#include <NOX_SolverStats.hpp>
#include <NOX_Thyra.H>
#include <Thyra_TpetraThyraWrappers.hpp>

#include "solvers/linear/MumpsPreconditioner.hpp"

namespace glossa::solvers {

using Teuchos::RCP;
using Teuchos::rcp;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, assembly::LO, assembly::GO, assembly::Node>;

namespace {

RCP<const assembly::Vector> displacementOf(const NOX::Abstract::Vector &x) {
  return Extract::getConstTpetraVector(dynamic_cast<const NOX::Thyra::Vector &>(x).getThyraRCPVector());
}

// The Newton iterations of the corrector: every accepted iterate becomes the base of the next
// three-field linearisation (as in NewtonSolver), and the iterations are counted per point.
class CorrectorObserver : public NOX::Observer {
public:
  explicit CorrectorObserver(assembly::ModelEvaluator &model) : model_(model) {}
  // A fresh MUMPS factor for every bordered solve: a factor kept from the last iterate (Linear
  // solver/direct reuse iterations) made the sphere's path 9x slower (141 against 15 s), its
  // Krylov solves stalling as the tangent nears singularity at the load maximum.
  void runPreIterate(const NOX::Solver::Generic &) override { MumpsPreconditionerFactory::beginStep(); }
  void runPostIterate(const NOX::Solver::Generic &solver) override {
    const auto &x = dynamic_cast<const LOCA::MultiContinuation::ExtendedVector &>(solver.getSolutionGroup().getX());
    model_.advanceIterates(*displacementOf(*x.getXVec()));
    ++newton;
  }
  // Since the last converged point. (The Krylov iterations of LOCA's bordered solves do not reach
  // NOX's statistics: they are not counted.)
  int newton = 0;

private:
  assembly::ModelEvaluator &model_;
};

// LOCA hands every converged point to its group's save strategy: here it goes to the caller,
// who records it and may end the path.
class PointHandler : public LOCA::Thyra::SaveDataStrategy {
public:
  PointHandler(assembly::ModelEvaluator &model, CorrectorObserver &observer, const ArcLengthCallback &onPoint,
               const ArcLengthSettings &settings)
      : model_(model), observer_(observer), onPoint_(onPoint), settings_(settings) {}
  void saveSolution(const NOX::Abstract::Vector &x, double p) override {
    // Once the path has ended, LOCA may still try a last step towards its parameter bound
    // (past a load maximum it fails): nothing after the end is the caller's.
    if (stop) return;
    const RCP<const assembly::Vector> u = displacementOf(x);
    // The next corrector's three-field iterates start from the exact condensation here.
    model_.resetIterates(*u);
    last_ = rcp(new assembly::Vector(*u, Teuchos::Copy));
    if (steps_ < 0) { // LOCA's step 0: the start, already recorded by the caller
      steps_ = 0;
      observer_.newton = 0;
      return;
    }
    ArcLengthPoint point;
    point.step = ++steps_;
    point.time = p;
    point.newtonIterations = observer_.newton;
    observer_.newton = 0;
    if (!onPoint_(point, *u)) stop = true;
    // The path ends at the end time's load, or back at no load. LOCA caps its last step at the
    // bound but may not stop there (measured: it turned and went back down the branch it came up).
    // Back at no load only on the way down: a first step as small as `near` is not the path's end.
    const double near = 1e-6 * std::max(settings_.endTime, settings_.stepSize);
    const bool falling = p < previous_;
    previous_ = p;
    if (!stop && (p >= settings_.endTime - near || (falling && p <= near))) stop = true;
    if (!stop && steps_ >= settings_.maximumSteps) stop = exhausted = true;
  }
  void preProcessContinuationStep(LOCA::Abstract::Iterator::StepStatus status) override {
    // A failed corrector left its iterates in the three-field bases: back to the last point.
    if (status == LOCA::Abstract::Iterator::Unsuccessful && !last_.is_null()) model_.resetIterates(*last_);
    observer_.newton = 0;
    MumpsPreconditionerFactory::beginStep(); // for the predictor's solve
  }
  int steps() const { return std::max(steps_, 0); }
  bool stop = false;      // the caller ended the path, or it took its steps
  bool exhausted = false; // it took its steps

private:
  assembly::ModelEvaluator &model_;
  CorrectorObserver &observer_;
  const ArcLengthCallback &onPoint_;
  RCP<assembly::Vector> last_;
  int steps_ = -1;
  const ArcLengthSettings &settings_;
  double previous_ = settings_.startTime; // the last point's load
};

// Ends the path when the caller said so (LOCA asks after every step).
class CallerStop : public LOCA::StatusTest::Abstract {
public:
  explicit CallerStop(PointHandler &handler) : handler_(handler) {}
  LOCA::StatusTest::StatusType checkStatus(const LOCA::Abstract::Iterator &, LOCA::StatusTest::CheckType) override {
    status_ = handler_.stop ? LOCA::StatusTest::Finished : LOCA::StatusTest::NotFinished;
    return status_;
  }
  LOCA::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream &print(std::ostream &stream, int indent) const override {
    for (int i = 0; i < indent; ++i) stream << ' ';
    return stream << "stop asked by the caller: " << (handler_.stop ? "yes" : "no") << '\n';
  }

private:
  PointHandler &handler_;
  LOCA::StatusTest::StatusType status_ = LOCA::StatusTest::Unevaluated;
};

RCP<Teuchos::ParameterList> locaParameters(const ArcLengthSettings &s, const RCP<NOX::Observer> &observer) {
  auto params = Teuchos::parameterList("LOCA and NOX");
  Teuchos::ParameterList &stepper = params->sublist("LOCA").sublist("Stepper");
  stepper.set("Continuation Method", "Arc Length");
  stepper.set("Continuation Parameter", "time");
  stepper.set("Initial Value", s.startTime);
  stepper.set("Max Value", s.endTime);
  stepper.set("Min Value", 0.0);
  stepper.set("Max Steps", 4 * s.maximumSteps); // a backstop: PointHandler counts the converged ones
  stepper.set("Max Nonlinear Iterations", s.maximumNewtonIterations);
  stepper.set("Compute Eigenvalues", false);
  stepper.set("Return Failed on Reaching Max Steps", true);
  // Tangent: the predictor solves K du/dt = -df/dt (LOCA's finite difference in t at fixed u).
  params->sublist("LOCA").sublist("Predictor").set("Method", "Tangent");
  Teuchos::ParameterList &step = params->sublist("LOCA").sublist("Step Size");
  step.set("Method", "Adaptive");
  step.set("Initial Step Size", s.stepSize);
  step.set("Max Step Size", s.stepSize);
  step.set("Min Step Size", s.minimumStepSize);
  step.set("Aggressiveness", 0.5);
  Teuchos::ParameterList &nox = params->sublist("NOX");
  nox.set("Nonlinear Solver", "Line Search Based");
  nox.sublist("Line Search").set("Method", "Full Step");
  nox.sublist("Direction").sublist("Newton").sublist("Linear Solver").set("Tolerance", s.linearTolerance);
  nox.sublist("Printing").set("Output Information", NOX::Utils::Error);
  nox.sublist("Solver Options").set<RCP<NOX::Observer>>("User Defined Pre/Post Operator", observer);
  // LOCA prints its status tests' verdict and step-size messages whatever the print level: the
  // log is Glossa's.
  params->sublist("LOCA").sublist("Utilities").set("Output Information", 0);
  auto quiet = rcp(new Teuchos::oblackholestream);
  params->sublist("LOCA").sublist("Utilities").set<RCP<std::ostream>>("Output Stream", quiet);
  // Its step-size messages too ("minimum step size bound"): Glossa names why a path ended.
  params->sublist("LOCA").sublist("Utilities").set<RCP<std::ostream>>("Error Stream", quiet);
  nox.sublist("Printing").set<RCP<std::ostream>>("Output Stream", quiet);
  return params;
}

} // namespace

ArcLengthOutcome followPath(const RCP<assembly::ModelEvaluator> &model, const assembly::Vector &u,
                            const ArcLengthSettings &settings, const ArcLengthCallback &onPoint) {
  auto observer = rcp(new CorrectorObserver(*model));
  auto params = locaParameters(settings, observer);
  RCP<LOCA::GlobalData> globalData = LOCA::createGlobalData(params);

  LOCA::ParameterVector p;
  p.addParameter("time", settings.startTime);
  model->resetIterates(u);
  auto uCopy = rcp(new assembly::Vector(u, Teuchos::Copy));
  NOX::Thyra::Vector initialGuess(Thyra::createVector(RCP<assembly::Vector>(uCopy), model->get_x_space()));
  auto group = rcp(new LOCA::Thyra::Group(globalData, initialGuess, model, p, 0));
  auto handler = rcp(new PointHandler(*model, *observer, onPoint, settings));
  group->setSaveDataStrategy(handler);

  using namespace NOX::StatusTest;
  auto tests = rcp(new Combo(Combo::OR));
  tests->addStatusTest(rcp(new FiniteValue));
  // The bordered residual [f; arc-length constraint]: the constraint is linear in (u, t), so
  // after the first iteration its part is round-off and the test is on f.
  tests->addStatusTest(rcp(new NormF(settings.residualTolerance, NormF::Unscaled)));
  tests->addStatusTest(rcp(new MaxIters(settings.maximumNewtonIterations)));

  ArcLengthOutcome outcome;
  try {
    LOCA::Stepper stepper(globalData, group, rcp(new CallerStop(*handler)), tests, params);
    const LOCA::Abstract::Iterator::IteratorStatus status = stepper.run();
    outcome.completed = (status == LOCA::Abstract::Iterator::Finished || handler->stop) && !handler->exhausted;
    if (handler->exhausted)
      outcome.failure = "the path took Time/arc length steps = " + std::to_string(settings.maximumSteps) +
                        " steps without reaching its end; raise Time/arc length steps or Time/step size";
    else if (!outcome.completed)
      outcome.failure = "LOCA's corrector failed below the minimum step size";
  } catch (const std::exception &e) {
    outcome.failure = std::string("arc-length continuation failed: ") + e.what();
  }
  outcome.steps = handler->steps();
  LOCA::destroyGlobalData(globalData);
  return outcome;
}

} // namespace glossa::solvers
