#include "solvers/run/PathFollowing.hpp"

#include <cstdio>

#include "assembly/Assembler.hpp"
#include "assembly/ModelEvaluator.hpp"
#include "assembly/ResultEvaluator.hpp"
#include "solvers/incompressibility/UzawaLoop.hpp"
#include "solvers/run/RunSetup.hpp"

namespace glossa::solvers {

namespace {
// A converged point of the path as a step trial from the committed state, with its checks.
StepTrial &pointTrial(RunParts &run, const ArcLengthPoint &point, const assembly::Vector &u) {
  StepTrial &trial = run.stepper->beginTrial(point.time, run.model->assemblySeconds());
  StepAttempt &a = trial.attempt;
  // LOCA's point carries the Krylov error at the constrained dofs (the residual ignores them,
  // Assembler::importPrescribed): the recorded state holds the prescribed values exactly.
  trial.state.u.assign(u);
  run.assembler->applyDirichlet(trial.state.u, point.time);
  a.uzawa.converged = true;
  a.uzawa.solves = 1;
  a.uzawa.newtonIterations = point.newtonIterations;
  a.uzawa.dilatation =
      run.uzawa->dilatationError(
          assembly::ResultEvaluator(*run.assembler).elementDilatations(trial.state.u, run.stepper->committed().lambda));
  a.ok = true;
  run.solver->measureCorners(trial.state, point.time, a);
  if (a.ok) run.solver->refuseInsideOut(trial.state, a);
  return trial;
}
} // namespace

void followArcLength(RunParts &run, const std::function<void()> &commit) {
  ArcLengthSettings settings = *run.arcLength;
  settings.startTime = run.stepper->time();
  run.model->setMultipliers(run.stepper->committed().lambda);
  run.model->setTime(run.stepper->time());
  nlohmann::json &doc = run.report->doc();

  double highest = run.stepper->time(); // the largest load so far, and whether the path has turned down from it
  bool turned = false;
  auto onPoint = [&](const ArcLengthPoint &point, const assembly::Vector &u) {
    const StepTrial &trial = pointTrial(run, point, u);
    if (!trial.attempt.ok) {
      if (!trial.attempt.folded.is_null()) doc["folded_element"] = trial.attempt.folded;
      else doc["inside_out_refusals"].push_back(trial.attempt.insideOut);
      run.report->fail("arc-length step " + std::to_string(point.step) + ": " + trial.attempt.why);
      return false;
    }
    commit();
    if (point.time > highest) highest = point.time;
    else if (!turned) {
      // The load passed a maximum between the last two points: named once, as load control would.
      turned = true;
      doc["load_maximum"] = {{"time", highest}, {"step", run.stepper->stepNumber() - 1}};
      if (run.talk) std::printf("  note: the path passed a load maximum near t = %.6g and follows the falling branch\n", highest);
    }
    const double largest = largestMotion(assembly::ResultEvaluator(*run.assembler), run.stepper->committed().u).norm;
    if (run.report->stopRequested(run.stepper->stepNumber(), run.stepper->time())) return false;
    return !(settings.stopAtDisplacement > 0.0 && largest >= settings.stopAtDisplacement);
  };
  const ArcLengthOutcome outcome = followPath(run.model, run.stepper->committed().u, settings, onPoint);
  doc["path_following"] = {{"method", "arc length (LOCA)"}, {"steps", outcome.steps}, {"largest_time", highest}};
  if (!outcome.completed && run.report->converged()) run.report->fail(outcome.failure);
}

} // namespace glossa::solvers
