#include "solvers/run/Simulation.hpp"

#include <cstdio>

#include "assembly/Assembler.hpp"
#include "assembly/ContactResponse.hpp"
#include "assembly/ModelEvaluator.hpp"
#include "assembly/ResultEvaluator.hpp"
#include "assembly/TimeSplit.hpp"
#include "model/Scene.hpp"
#include "solvers/incompressibility/UzawaLoop.hpp"
#include "solvers/nonlinear/NewtonSolver.hpp"
#include "solvers/run/AirflowCoupling.hpp"
#include "solvers/run/PathFollowing.hpp"
#include "solvers/run/RunSetup.hpp"

namespace glossa::solvers {

Simulation::Simulation(const io::Deck &deck, const RunConfiguration &config,
                       const Teuchos::RCP<const Teuchos::Comm<int>> &comm, const RunOptions &options)
    : run_(setUpRun(deck, config, comm, options)) {
  RunParts &run = *run_;
  onPath_ = run.config.time.pathFollowing == PathFollowing::arcLength;
  run.report->describeSolves(run.linearPlan.direct,
                             run.config.incompressibility.method == IncompressibilityMethod::penalty);
  const StepState &state = run.stepper->committed();
  const assembly::MuscleFields initial = assembly::updateMuscleHistory(assembly::ResultEvaluator(*run.assembler), state.u, *run.history);
  std::vector<double> inputs;
  for (std::size_t g = 0; g < run.scene->muscles.groups.size(); ++g)
    inputs.push_back(run.history->input(static_cast<int>(g), 0.0));
  if (!run.restart)
    run.report->recordingOutputFailure([&] {
      // The contacts at the reference state (what touches before any load), as the other CSVs'
      // t = 0 rows; recorded first, for the fields.
      const auto contacts = assembly::updateContactStates(assembly::ResultEvaluator(*run.assembler), state.u);
      run.recorder->record(0.0, state.u, state.lambda, true, initial, inputs);
      run.recorder->recordContacts(0.0, contacts);
      run.recorder->recordAirway(0.0, contacts);
      if (run.airflow)
        run.recorder->recordAirflow(
            0.0, run.airflow->flowAt(0.0, assembly::ResultEvaluator(*run.assembler).gatherDisplacement(state.u)));
      recordEnergy(nullptr);
      run.report->write(assemblyCounters(*run.model));
    });
  if (run.controlled) run.controlled->setCommittedStretch(initial.groupMeanStretch);
  if (run.restart) restoreRun(run, *run.restart);
  // A restart's checkpoint is an open state (none is written inside the bracket): the search's start.
  if (run.pcrit) run.pcrit->opened(run.stepper->time());
  run.report->beginSteps(run.stepper->time());
}

Simulation::~Simulation() = default;

void Simulation::attempt(StepTrial &trial) {
  RunParts &run = *run_;
  if (run.detail) std::printf("step %d  t = %.6g  dt = %.3g\n", run.stepper->stepNumber() + 1, trial.time, trial.dt);
  if (run.controlled) run.controlled->step(trial, run.stepper->stepNumber());
  else trial.attempt = run.solver->solve(trial.time, trial.dt, trial.state, false);
  if (trial.attempt.ok && run.watch) run.watch->check(trial);
}

void Simulation::commit() {
  RunParts &run = *run_;
  const StepTrial &trial = run.stepper->trial();
  // A controlled step's winner may have been solved by another control group, whose statistics
  // carry no multipliers: every group takes them from the trial state alike.
  if (run.controlled && run.uzawa->augmentedLagrangian() && !run.uzawa->mixedPressure())
    run.stepper->commit(run.uzawa->nextMultipliers(
        assembly::ResultEvaluator(*run.assembler).elementDilatations(trial.state.u, trial.state.lambda)));
  else run.stepper->commit(trial.attempt.uzawa.nextMultipliers);
  const double t = run.stepper->time();
  // At the converged state, before the muscle history is committed: the quasi-static forces it
  // keeps are those the step was solved with.
  if (run.inertia) run.inertia->commit(run.stepper->committed(), t);
  if (run.watch && !onPath_) run.watch->accepted(t, trial.attempt.pathStiffness);
  // The muscle history is committed after the output, whose stresses are those of the converged
  // state: this step's activation with the committed lambda_c it was solved with.
  auto output = run.report->holdOutput();
  const assembly::PartTimer outputTimer(assembly::TimedPart::stepOutput);
  record(trial);
  if (run.controlled) run.controlled->committed(trial);
  run.history->commit();
  for (const auto &contact : run.scene->contacts)
    if (contact.state) contact.state->commit();
  run.report->stepLine(run.stepper->stepNumber(), t, run.stepper->steps().endTime(), trial.dt, trial.attempt.uzawa,
                       onPath_, run.controlled ? run.controlled->controlLine() : std::string());
  if (run.newton->guardsSteps()) run.report->doc()["newton_step_halvings"] = run.newton->halvedSteps();
  run.report->write(assemblyCounters(*run.model));
  output.unlock();
  // Inside the closing pressure's bracket no checkpoint is written: a restart resumes before the
  // closing step and bisects again to the same bracket.
  const bool bisecting = run.pcrit && run.pcrit->bracketing();
  if (run.checkpoints->due(run.stepper->stepNumber()) && !onPath_ && !bisecting) writeCheckpoint(run);
}

bool Simulation::trialClosesAirway() {
  RunParts &run = *run_;
  const StepTrial &trial = run.stepper->trial();
  // Every rank gathers the whole displacement and measures the same lumen, so all agree.
  const std::vector<double> uAll = assembly::ResultEvaluator(*run.assembler).gatherDisplacement(trial.state.u);
  const std::optional<int> section = run.pcrit->closedSection(run.airway->positions(run.scene->mesh, uAll));
  if (!section) return false;
  if (run.talk)
    std::printf("  the airway closes at t = %.9g (%.6g Pa, section %d); not committed: bisecting from t = %.9g\n",
                trial.time, run.pcrit->pressure(trial.time), *section, run.stepper->time());
  run.pcrit->closed(trial.time, *section);
  return true;
}

bool Simulation::pcritGoesOn(bool closed) {
  RunParts &run = *run_;
  if (!closed) run.pcrit->opened(run.stepper->time());
  if (!run.pcrit->bracketing()) return true;
  if (run.pcrit->found()) return false;
  if (run.stepper->setStepSize(run.pcrit->nextStep(run.stepper->time()))) return true;
  run.report->warn("the closing pressure's bisection stopped at the minimum step size before the bracket reached "
                   "'closing pressure tolerance'");
  return false;
}

void Simulation::record(const StepTrial &trial) {
  RunParts &run = *run_;
  const StepState &state = run.stepper->committed();
  const bool fields = run.stepper->finished() || run.stepper->stepNumber() % run.config.output.every == 0;
  const AirflowStep airflow = run.airflow ? committedAirflow(trial) : AirflowStep{};
  const auto reactions = run.recorder->record(run.stepper->time(), state.u, state.lambda, fields, trial.attempt.muscle,
                                              run.history->trialInput(), fieldsStamp());
  run.recorder->recordContacts(run.stepper->time(), trial.attempt.uzawa.contacts);
  run.recorder->recordAirway(run.stepper->time(), trial.attempt.uzawa.contacts);
  nlohmann::json step, forces = nlohmann::json::object();
  if (run.airflow) recordAirflow(airflow, step);
  for (const auto &[name, row] : reactions) forces[name] = std::vector<double>(row.begin(), row.begin() + 3);
  step["reactions"] = forces;
  if (!run.scene->muscles.groups.empty()) {
    nlohmann::json activation = nlohmann::json::object();
    for (const auto &[group, v] : run.recorder->activationRows(trial.attempt.muscle, run.history->trialInput()))
      activation[group] = {{"u", v[0]}, {"alpha", v[1]}, {"ffmr", v[2]}, {"mean_fibre_stretch", v[3]},
                           {"mean_contractile_stretch", v[4]}};
    step["activation"] = activation;
  }
  recordContacts(trial.attempt.uzawa, step);
  recordEnergy(&step);
  if (trial.attempt.uzawa.augmentationRaises > 0) step["penalty_ratios"] = run.uzawa->penaltyRatios();
  if (run.controlled) step["control"] = run.controlled->record(trial, run.stepper->time());
  run.report->addStep(trial, run.stepper->time(), onPath_, run.model->assemblySeconds(), step);
}

void Simulation::recordContacts(const UzawaResult &uzawa, nlohmann::json &step) {
  RunParts &run = *run_;
  if (uzawa.contacts.empty()) return;
  nlohmann::json contacts = nlohmann::json::object();
  nlohmann::json &overall = run.report->doc()["contact"];
  if (!overall.is_object()) overall = nlohmann::json::object(); // the first step
  bool met = overall.value("gap_tolerance_met", true);
  double largest = overall.value("largest_gap_error", 0.0);
  for (std::size_t c = 0; c < uzawa.contacts.size(); ++c) {
    const contact::ContactMeasures &m = uzawa.contacts[c];
    const model::RigidContact &contact = run.scene->contacts[c];
    contacts[contact.name] = {{"area", m.area}, {"normal_force", m.normalForce}, {"tangential_force", m.tangentialForce},
                              {"largest_penetration", m.largestPenetration}, {"active_points", m.activePoints},
                              {"largest_gap_error", m.largestGapError}, {"gap_met", m.gapMet()},
                              {"enforcement", contact.augmented() ? "augmented Lagrangian" : "penalty"}};
    if (contact.augmented()) {
      met = met && m.gapMet();
      largest = std::max(largest, m.largestGapError);
    }
  }
  step["contacts"] = contacts;
  step["contact_updates"] = uzawa.contactUpdates;
  // Over the run: every step's augmented contacts within their gap tolerance, and the largest
  // gap error any of them ended a step with.
  overall = {{"gap_tolerance_met", met}, {"largest_gap_error", largest}};
}

AirflowStep Simulation::committedAirflow(const StepTrial &trial) {
  RunParts &run = *run_;
  if (trial.attempt.airflow.on) return trial.attempt.airflow;
  // A controlled step's winner was solved among candidates: its flow is measured again at the
  // committed state (the flow its pressures came from, to the coupling tolerance), and its face
  // pressures set again for the output fields (the last candidate solved left its own).
  AirflowStep airflow = run.airflow->flowAt(
      run.stepper->time(), assembly::ResultEvaluator(*run.assembler).gatherDisplacement(run.stepper->committed().u));
  if (!airflow.sectionPressure.empty()) run.airflow->showPressures(airflow.sectionPressure);
  // The winner's coupling, as its control group solved it.
  airflow.iterations = trial.control.couplingIterations;
  airflow.residual = trial.control.couplingChange;
  return airflow;
}

void Simulation::recordAirflow(const AirflowStep &airflow, nlohmann::json &step) {
  RunParts &run = *run_;
  run.recorder->recordAirflow(run.stepper->time(), airflow);
  step["airflow"] = {{"flow_rate", airflow.flowRate},         {"smallest_area", airflow.smallestArea},
                     {"smallest_section", airflow.smallestSection}, {"closed", airflow.closed},
                     {"coupling_iterations", airflow.iterations}, {"coupling_change", airflow.residual}};
  nlohmann::json &overall = run.report->doc()["airflow"];
  if (!overall.is_object()) overall = {{"coupling_iterations", 0}, {"largest_coupling_iterations", 0}};
  overall["coupling_iterations"] = overall["coupling_iterations"].get<int>() + airflow.iterations;
  overall["largest_coupling_iterations"] = std::max(overall["largest_coupling_iterations"].get<int>(), airflow.iterations);
}

void Simulation::recordEnergy(nlohmann::json *step) {
  RunParts &run = *run_;
  if (!run.inertia) return;
  const StepState &state = run.stepper->committed();
  StepEnergy energy;
  energy.kinetic = run.inertia->kineticEnergy();
  energy.stored = assembly::ResultEvaluator(*run.assembler).storedEnergy(state.u, state.lambda);
  run.recorder->recordEnergy(run.stepper->time(), energy);
  if (step) (*step)["energy"] = {{"kinetic", energy.kinetic}, {"strain", energy.stored}, {"total", energy.total()}};
}

bool Simulation::rollBack() {
  RunParts &run = *run_;
  const StepTrial &trial = run.stepper->trial();
  if (!trial.attempt.folded.is_null()) {
    // A fold is where the path leads, not a failed solve: a smaller step converges to it again.
    run.report->doc()["folded_element"] = trial.attempt.folded;
    run.report->fail(trial.attempt.why);
    return false;
  }
  run.report->stepRefused(trial);
  const bool stepLeft = run.stepper->cutBack();
  if (run.watch) {
    const PathWatch::Verdict verdict = run.watch->refused(run.stepper->time(), trial, run.stepper->committed(),
                                                          run.stepper->steps().stepSize(), stepLeft);
    if (verdict.located) {
      nlohmann::json &limit = run.report->doc()["limit_point"] = verdict.record;
      if (!run.arcLength) {
        run.report->fail(verdict.description);
        return false;
      }
      switchToPath_ = true; // at a limit point = follow: the path goes on from the last accepted state
      if (run.talk)
        std::printf("  note: a limit point of the load path between t = %.6g and %.6g s (summary.json: limit_point); "
                    "following the path past it by arc-length continuation\n",
                    limit["bracket"][0].get<double>(), limit["bracket"][1].get<double>());
      return false;
    }
  }
  if (stepLeft) return true;
  run.report->fail("step to t = " + std::to_string(trial.time) + " failed (" + trial.attempt.why +
                   ") below the minimum step size");
  return false;
}

std::optional<double> Simulation::fieldsStamp() const {
  if (!onPath_) return std::nullopt;
  return pathStartTime_ + (run_->stepper->stepNumber() - pathStartStep_) * run_->stepper->steps().nominalStep();
}

void Simulation::followPath() {
  onPath_ = true;
  pathStartTime_ = run_->stepper->time();
  pathStartStep_ = run_->stepper->stepNumber();
  followArcLength(*run_, [this] { commit(); });
}

void Simulation::finish() {
  RunParts &run = *run_;
  // Stopped by a signal: the committed state is sound, so it is kept for --restart.
  if (run.report->stoppedBy() != 0 && run.checkpoints->enabled() && !onPath_) writeCheckpoint(run);
  const std::vector<double> uAll = assembly::ResultEvaluator(*run.assembler).gatherDisplacement(run.stepper->committed().u);
  if (run.options.finalDisplacement) *run.options.finalDisplacement = uAll;
  nlohmann::json finals = nlohmann::json::object();
  for (const auto &[name, d] : run.recorder->pointDisplacements(uAll)) finals[name] = {d.x(), d.y(), d.z()};
  if (run.pcrit) {
    const double reached = run.stepper->time(), end = run.stepper->steps().endTime();
    run.report->doc()["pcrit"] = run.pcrit->summary(reached, end);
    if (run.talk) std::printf("%s\n", run.pcrit->line(reached, end).c_str());
  }
  run.report->finish(assemblyCounters(*run.model), run.stepper->time(), finals);
}

nlohmann::json Simulation::run() {
  RunParts &run = *run_;
  const auto onRetry = [&run](const StepTrial &trial) {
    if (run.talk)
      std::printf("  step failed at t = %.6g from the extrapolated state: %s; again from the last converged state\n",
                  trial.time, trial.attempt.why.c_str());
    run.report->doc()["predictor_retries"] = run.report->doc().value("predictor_retries", 0) + 1;
  };
  run.report->recordingOutputFailure([&] {
    while (!onPath_ && !run.stepper->finished()) {
      if (run.report->stopRequested(run.stepper->stepNumber(), run.stepper->time())) break;
      if (run.stepper->attemptStep(*this, run.model->assemblySeconds(), onRetry)) {
        const bool closed = run.pcrit && trialClosesAirway();
        if (!closed) commit();
        if (run.pcrit && !pcritGoesOn(closed)) break;
      } else if (!rollBack()) break;
    }
    if (onPath_ || switchToPath_) followPath();
    finish();
  });
  return run.report->doc();
}

nlohmann::json runSimulation(const io::Deck &deck, const RunConfiguration &config,
                             const Teuchos::RCP<const Teuchos::Comm<int>> &comm, const RunOptions &options) {
  Simulation simulation(deck, config, comm, options);
  return simulation.run();
}

} // namespace glossa::solvers
