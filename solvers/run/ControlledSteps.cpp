#include "solvers/run/ControlledSteps.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "airway/ResponseProbe.hpp"
#include "assembly/Assembler.hpp"
#include "assembly/ModelEvaluator.hpp"
#include "assembly/ResultEvaluator.hpp"
#include "io/output/KeyedCsvWriter.hpp"
#include "model/AirwayOutput.hpp"
#include "model/Scene.hpp"
#include "solvers/control/CommControlGroups.hpp"
#include "solvers/control/ControlSensitivity.hpp"
#include "solvers/incompressibility/ConstrainedTangent.hpp"
#include "solvers/linear/MumpsPreconditioner.hpp"
#include "solvers/incompressibility/UzawaLoop.hpp"
#include "solvers/run/LoadStepper.hpp"

namespace glossa::solvers {

ControlledSteps::ControlledSteps(const ControlSetup &setup, const StepSolverParts &parts, const StepSolver &solver,
                                 const LoadStepper &stepper, const CommControlGroups &groups,
                                 const std::filesystem::path &dir, std::optional<std::uintmax_t> resumeControlsAt,
                                 bool writer, bool talk, std::shared_ptr<const model::AirwayOutput> airway,
                                 Augmentation *augmentation, bool constrainedSensitivity)
    : setup_(setup), parts_(parts), solver_(solver), stepper_(stepper), last_(stepper.committed()),
      kept_(stepper.committed()), seed_(stepper.committed()), augmentation_(augmentation),
      constrainedSensitivity_(constrainedSensitivity && augmentation != nullptr), airway_(std::move(airway)) {
  if (writer)
    controls_ = std::make_unique<io::KeyedCsvWriter>(
        dir / "controls.csv", "group",
        std::vector<std::string>{"u [-]", "evaluated [-]", "objective [m]", "candidates [-]"}, resumeControlsAt);
  const model::Scene &scene = parts.assembler.scene();
  ControlDriverSetup driver;
  driver.parameters = setup.parameters;
  for (const auto &g : scene.muscles.groups) driver.groupNames.push_back(g.name);
  driver.controlled = setup.groups;
  driver.referencePositions.resize(3, static_cast<Eigen::Index>(setup.pointNodes.size()));
  for (std::size_t p = 0; p < setup.pointNodes.size(); ++p)
    driver.referencePositions.col(static_cast<Eigen::Index>(p)) = scene.mesh.nodes[setup.pointNodes[p]];
  driver.goals = setup.goals;
  driver.weights = setup.weights;
  driver.talk = talk;
  driver_ = std::make_unique<ControlDriver>(std::move(driver), *this, groups);
}

ControlledSteps::~ControlledSteps() = default;

std::vector<double> ControlledSteps::stepInputs(const std::vector<double> &inputs, double time) const {
  std::vector<double> step(inputs.size());
  for (std::size_t g = 0; g < step.size(); ++g) step[g] = parts_.history.input(static_cast<int>(g), time);
  for (int g : setup_.groups) step[g] = inputs[g];
  return step;
}

Eigen::Matrix3Xd ControlledSteps::pointDisplacement(const std::vector<double> &all) const {
  Eigen::Matrix3Xd d(3, static_cast<Eigen::Index>(setup_.pointNodes.size()));
  for (std::size_t p = 0; p < setup_.pointNodes.size(); ++p) {
    const auto n = setup_.pointNodes[p];
    d.col(static_cast<Eigen::Index>(p)) = Eigen::Vector3d(all[3 * n], all[3 * n + 1], all[3 * n + 2]);
  }
  return d;
}

StepAttempt ControlledSteps::solveFrom(const std::vector<double> &inputs, const StepState *from,
                                       const CandidateStart *start, double loadScale, StartOutcome &outcome) {
  outcome = StartOutcome{};
  const StepTrial &trial = stepper_.trial();
  UzawaResult predicted; // the counts of a predicted start that failed
  if (from) {
    last_.assign(*from);
    start->predict(inputs, parts_.uzawa, last_);
    StepAttempt a = solver_.solve(trial.time, trial.dt, last_, true, stepInputs(inputs, trial.time), loadScale);
    // A start moved too far (an element turned inside out on the way, which its first residual
    // finds) is no reason to fail: the step's start is tried as without a prediction, its counts
    // added. (Half the move instead, tried on the supine GA deck, saved no Newton iterations.)
    if (a.ok) return a;
    if (screensTurnedOverStarts() && a.uzawa.elementInverted) {
      outcome.screened = true;
      a.why = "its moved start turned an element over (not retried: Control/retry turned-over starts = false)";
      return a;
    }
    // Converged, but with an element folded through itself: the fold is the equilibrium's at these
    // inputs, not the start's. From the step's start Newton converged to the same fold every time
    // it was asked to, with 21-25 Newton iterations more where the moved start had taken 3-8 (the
    // medium tongue's gradient decks: doc/control.md, "Folded candidates are not solved again"),
    // so the candidate fails here.
    if (!a.folded.is_null()) return a;
    predicted = a.uzawa;
    outcome.solvedAgain = true;
  }
  last_.assign(stepper_.stepStart());
  StepAttempt a = solver_.solve(trial.time, trial.dt, last_, true, stepInputs(inputs, trial.time));
  a.uzawa.solves += predicted.solves;
  a.uzawa.newtonIterations += predicted.newtonIterations;
  a.uzawa.linearIterations += predicted.linearIterations;
  a.uzawa.contactUpdates += predicted.contactUpdates;
  return a;
}

bool ControlledSteps::screensTurnedOverStarts() const {
  const control::ControllerParameters &p = setup_.parameters;
  return p.type == control::ControllerType::geneticAlgorithm && !p.retryTurnedOverStarts;
}

CandidateSolve ControlledSteps::solve(const std::vector<double> &inputs) {
  StartOutcome started;
  StepAttempt a = start_.ready()       ? solveFrom(inputs, &kept_, &start_, keptLoadScale_, started)
                  : seedStart_.ready() ? solveFrom(inputs, &seed_, &seedStart_, seedLoadScale_, started)
                                       : solveFrom(inputs, nullptr, nullptr, 0.0, started);
  lastLoadScale_ = a.loadScale;
  CandidateSolve out;
  out.ok = a.ok;
  out.screened = started.screened;
  out.solvedAgain = started.solvedAgain;
  out.why = a.why;
  out.statistics = std::move(a.uzawa);
  out.couplingIterations = a.airflow.iterations;
  out.couplingChange = a.airflow.residual;
  if (a.ok) {
    const std::vector<double> all = assembly::ResultEvaluator(parts_.assembler).gatherDisplacement(last_.u);
    out.pointDisplacement = pointDisplacement(all);
    if (measuresLumen()) out.smallestArea = lumenArea(all);
  }
  return out;
}

double ControlledSteps::lumenArea(const std::vector<double> &uAll, int section) const {
  const airway::LumenState lumen = airway_->measure(parts_.assembler.scene().mesh, uAll);
  const int k = section >= 0 ? section : lumen.smallest;
  return k >= 0 ? lumen.sections[static_cast<std::size_t>(k)].area() : std::numeric_limits<double>::quiet_NaN();
}

void ControlledSteps::keepLast() {
  kept_.assign(last_);
  keptLoadScale_ = lastLoadScale_;
  start_.forget();
}

ControlPointSensitivity ControlledSteps::keptSensitivity(const std::vector<double> &inputs, const std::vector<int> &groups,
                                                         bool constrained, CandidateStart *start) {
  const control::ControllerParameters &p = setup_.parameters;
  const bool augmented = parts_.uzawa.augmentedLagrangian() && !parts_.uzawa.mixedPressure();
  const assembly::ResultEvaluator results(parts_.assembler);
  parts_.model.setMultipliers(kept_.lambda);
  // The pressures the kept state's multipliers were updated from, and their linear change along
  // each response with the sensitivity's own volumetric laws (the start's multipliers).
  std::vector<double> pressure;
  if (start && augmented) pressure = results.elementDilatations(kept_.u, kept_.lambda).pressure;
  if (!constrained || !augmentation_) {
    ControlPointSensitivity s = controlPointSensitivity(parts_.newton, kept_.u, groups);
    if (start)
      start->record(inputs, groups, s.responses, pressure,
                    augmented ? elementPressureResponses(results, kept_.u, kept_.lambda, *s.responses)
                              : std::vector<std::vector<double>>{});
    return s;
  }
  // The converged loop's linearisation: the multipliers follow the pressures, so an element's
  // volume change costs the physical bulk modulus (capped), not the inner solves' kappa_t.
  ControlPointSensitivity s;
  {
    const ConstrainedTangent constrainedTangent(*augmentation_, results, kept_.u, kept_.lambda,
                                                p.sensitivityPenaltyRatio);
    parts_.model.setMultipliers(constrainedTangent.multipliers());
    // Fresh factors where Newton's direct solver serves the sensitivities (sensitivity solve =
    // as Newton): the last solve's, of the inner tangent, precondition this one poorly (16 block
    // Krylov iterations per sensitivity on the tongue instead of 1-2), in any reuse scope but run.
    MumpsPreconditionerFactory::beginStep();
    s = controlPointSensitivity(parts_.newton, kept_.u, groups);
    if (start)
      start->record(inputs, groups, s.responses, std::move(pressure),
                    elementPressureResponses(results, kept_.u, constrainedTangent.multipliers(), *s.responses));
  }
  parts_.model.setMultipliers(kept_.lambda);
  return s;
}

ControlPointSensitivity ControlledSteps::controllerSensitivity(const std::vector<double> &inputs,
                                                               const std::vector<int> &groups) {
  const bool predicts = setup_.parameters.predictedStart;
  if (setup_.parameters.type == control::ControllerType::gradient)
    return keptSensitivity(inputs, groups, constrainedSensitivity_, predicts ? &start_ : nullptr);
  // The GA's Gauss-Newton seed keeps the inner tangent (its seeds with the constrained one moved
  // the supine GA to inputs where most candidates failed: doc/control.md). Its state, which every
  // control group solved alike, is where the GA's candidates start, moved along the constrained
  // responses when the controller's rule would take them.
  if (!predicts) return keptSensitivity(inputs, groups, false, nullptr);
  seed_.assign(kept_);
  seedLoadScale_ = keptLoadScale_;
  if (!constrainedSensitivity_) return keptSensitivity(inputs, groups, false, &seedStart_);
  ControlPointSensitivity s = keptSensitivity(inputs, groups, false, nullptr);
  keptSensitivity(inputs, groups, true, &seedStart_);
  return s;
}

InputSensitivity ControlledSteps::sensitivity(const std::vector<double> &inputs, const std::vector<int> &groups) {
  const StepTrial &trial = stepper_.trial();
  parts_.model.beginStep(trial.time, trial.dt, stepInputs(inputs, trial.time));
  ControlPointSensitivity s;
  try {
    s = controllerSensitivity(inputs, groups);
  } catch (const std::runtime_error &e) {
    // A tangent solve that did not converge (Belos's verdict, the same on every rank) stops the
    // controller's search at what it has, instead of the run; later candidates start from the
    // step's start.
    parts_.model.setMultipliers(kept_.lambda);
    start_.forget();
    seedStart_.forget();
    InputSensitivity failed;
    failed.failure = e.what();
    return failed;
  }
  InputSensitivity out{s.dxdu, s.krylovIterations, {}, {}};
  if (measuresLumen()) {
    // dA/du_M of the kept state's smallest section: a central difference of the lumen along the
    // linearised response du/du_M (airway/ResponseProbe).
    const assembly::ResultEvaluator results(parts_.assembler);
    const std::vector<double> u = results.gatherDisplacement(kept_.u);
    const int smallest = airway_->measure(parts_.assembler.scene().mesh, u).smallest;
    out.dAdu = Eigen::RowVectorXd::Zero(static_cast<Eigen::Index>(groups.size()));
    for (std::size_t j = 0; smallest >= 0 && j < groups.size(); ++j) {
      const std::vector<double> du = results.gatherDisplacement(*s.responses->getVector(j));
      const double h = airway::probeStep(du);
      if (!(h > 0.0)) continue;
      out.dAdu(static_cast<Eigen::Index>(j)) =
          (lumenArea(airway::probed(u, du, h), smallest) - lumenArea(airway::probed(u, du, -h), smallest)) / (2.0 * h);
    }
  }
  return out;
}

std::vector<double> ControlledSteps::packKept() const {
  const assembly::ResultEvaluator results(parts_.assembler);
  std::vector<double> state = results.gatherDisplacement(kept_.u);
  const std::vector<double> lambdaAll = results.gatherElementField(kept_.lambda, 1);
  state.insert(state.end(), lambdaAll.begin(), lambdaAll.end());
  return state;
}

void ControlledSteps::unpackKept(const std::vector<double> &state) {
  const auto split = state.begin() + static_cast<long>(3 * parts_.assembler.scene().mesh.numNodes());
  const assembly::ResultEvaluator results(parts_.assembler);
  results.scatterDisplacement(std::vector<double>(state.begin(), split), kept_.u);
  kept_.lambda = results.localElementValues(std::vector<double>(split, state.end()));
  start_.forget();
}

void ControlledSteps::step(StepTrial &trial, int committedSteps) {
  start_.forget(); // another step: the last one's responses are of its state
  seedStart_.forget();
  trial.control = driver_->step(committedSteps, committedStretch_);
  if (!trial.control.found()) {
    trial.attempt.why = "no candidate input converged";
    return;
  }
  // The winner's trial muscle history (activation and lambda_c at its converged state, no
  // solve), then its state, become the trial's.
  parts_.model.beginStep(trial.time, trial.dt, stepInputs(trial.control.inputs, trial.time));
  trial.attempt.muscle = assembly::updateMuscleHistory(assembly::ResultEvaluator(parts_.assembler), kept_.u, parts_.history);
  trial.state.assign(kept_);
  trial.attempt.uzawa = trial.control.solve;
  trial.attempt.ok = true;
}

nlohmann::json ControlledSteps::record(const StepTrial &trial, double t) {
  const ControlStepResult &outcome = trial.control;
  const bool ga = setup_.parameters.type == control::ControllerType::geneticAlgorithm;
  nlohmann::json c;
  c["objective"] = outcome.objective;
  c["candidates"] = outcome.candidates;
  if (ga) {
    c["generations"] = outcome.generations;
    // The Gauss-Newton step of the prediction seed (Control/prediction seed).
    if (outcome.sensitivities > 0) c["sensitivity_evaluations"] = outcome.sensitivities;
  } else {
    c["iterations"] = outcome.iterations;
    c["sensitivity_evaluations"] = outcome.sensitivities;
    c["sensitivity_krylov"] = outcome.sensitivityKrylov;
    c["sensitivity_tangent"] = constrainedSensitivity_ ? "constrained" : "inner";
    if (outcome.sensitivityCheck >= 0.0) c["sensitivity_check"] = outcome.sensitivityCheck;
  }
  c["stop"] = outcome.stop;
  // Candidates whose solve failed are ranked last and otherwise silent: count them, with a reason.
  c["failed_candidates"] = outcome.failedCandidates;
  if (screensTurnedOverStarts()) c["screened_candidates"] = outcome.screenedCandidates;
  c["solved_again_candidates"] = outcome.solvedAgainCandidates;
  if (!outcome.firstFailure.empty()) c["first_candidate_failure"] = outcome.firstFailure;
  const auto &groups = parts_.assembler.scene().muscles.groups;
  nlohmann::json inputs = nlohmann::json::object(), errors = nlohmann::json::object();
  std::vector<std::pair<std::string, std::vector<double>>> rows;
  for (int g : setup_.groups) {
    const bool evaluated = std::find(outcome.evaluated.begin(), outcome.evaluated.end(), g) != outcome.evaluated.end();
    inputs[groups[g].name] = outcome.inputs[g];
    rows.push_back({groups[g].name,
                    {outcome.inputs[g], evaluated ? 1.0 : 0.0, outcome.objective, static_cast<double>(outcome.candidates)}});
  }
  for (std::size_t p = 0; p < setup_.pointNames.size(); ++p)
    errors[setup_.pointNames[p]] = outcome.pointErrors(static_cast<Eigen::Index>(p));
  c["inputs"] = inputs;
  c["point_errors"] = errors;
  if (controls_) controls_->append(t, rows);
  char failed[64];
  if (screensTurnedOverStarts())
    std::snprintf(failed, sizeof failed, "%zu failed, %zu of them screened", outcome.failedCandidates,
                  outcome.screenedCandidates);
  else
    std::snprintf(failed, sizeof failed, "%zu failed", outcome.failedCandidates);
  char line[240];
  std::snprintf(line, sizeof line, "  control: %s %.3g m, %zu candidates (%s), %s %d (%s)",
                measuresLumen() ? "eq. 25 + airway term" : "eq. 25", outcome.objective, outcome.candidates, failed,
                ga ? "generations" : "iterations", ga ? outcome.generations : outcome.iterations, outcome.stop.c_str());
  controlLine_ = line;
  return c;
}

void ControlledSteps::save(nlohmann::json &run) const {
  const auto memory = driver_->memory();
  run["control_memory"] = {memory.first, memory.second};
  run["committed_stretch"] = committedStretch_;
}

std::optional<std::uintmax_t> ControlledSteps::controlsBytes() const {
  if (!controls_) return std::nullopt;
  return controls_->bytes();
}

void ControlledSteps::restore(const nlohmann::json &run) {
  if (run.contains("control_memory"))
    driver_->restoreMemory({run.at("control_memory").at(0).get<control::Genome>(),
                            run.at("control_memory").at(1).get<control::Genome>()});
  committedStretch_ = run.at("committed_stretch").get<std::vector<double>>();
}

} // namespace glossa::solvers
