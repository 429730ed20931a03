#include "solvers/run/LoadStepper.hpp"

#include "assembly/RankAgreement.hpp"
#include "solvers/run/CheckpointContents.hpp"

namespace glossa::solvers {

LoadStepper::LoadStepper(const StepSizeRule &rule, bool extrapolate, const StepState &initial)
    : steps_(rule), extrapolate_(extrapolate), committed_(std::make_unique<StepState>(initial)),
      previous_(std::make_unique<StepState>(initial)), stepStart_(std::make_unique<StepState>(initial)) {}

bool LoadStepper::attemptStep(StepAttempter &attempter, double assemblySeconds,
                              const std::function<void(const StepTrial &)> &onRetry) {
  const double dt = steps_.nextStep(t_);
  const bool extrapolated = extrapolate_ && previousDt_ > 0.0;
  if (attemptFrom(attempter, dt, extrapolated, assemblySeconds) || !extrapolated || trial_->attempt.unstable)
    return trial_->attempt.ok;
  // The extrapolation can overshoot where the motion stops short, e.g. a muscle's jump from rest
  // in a first step carried on into the next (the protrusion scene: elements inverted, 8 steps
  // became 16 with cut-backs alone; bench/README.md).
  if (onRetry) onRetry(*trial_);
  return attemptFrom(attempter, dt, false, assemblySeconds);
}

bool LoadStepper::attemptFrom(StepAttempter &attempter, double dt, bool extrapolated, double assemblySeconds) {
  // The start of this step's solves: the committed state, or its linear extrapolation from the
  // step before (the multipliers too, so the Uzawa loop starts nearer its fixed point); with the
  // augmented Lagrangian the multipliers then come from MultiplierPredictor, one update ahead.
  stepStart_->assign(*committed_);
  if (extrapolated) {
    const double ratio = dt / previousDt_;
    stepStart_->u.update(-ratio, previous_->u, 1.0 + ratio);
    for (std::size_t e = 0; e < stepStart_->lambda.size(); ++e)
      stepStart_->lambda[e] += ratio * (committed_->lambda[e] - previous_->lambda[e]);
  }
  multipliers_.predict(dt, stepStart_->lambda);
  trial_ = std::make_unique<StepTrial>(t_ + dt, dt, assemblySeconds, *stepStart_);
  attempter.attempt(*trial_);
  agreeOnOutcome(trial_->attempt);
  return trial_->attempt.ok;
}

void LoadStepper::agreeOnOutcome(StepAttempt &attempt) const {
  // Whatever the attempter's checks are, a step that fails on one rank fails on all, for the
  // reason the lowest failing rank gives: a rank that committed while another cut back would
  // meet it in a different collective call.
  const assembly::Comm &comm = *committed_->u.getMap()->getComm();
  const auto failure =
      assembly::failureOnAnyRank(comm, attempt.ok ? std::nullopt : std::optional<std::string>(attempt.why));
  attempt.unstable = assembly::anyRank(comm, attempt.unstable);
  if (!failure) return;
  if (attempt.ok || attempt.why != failure->reason) attempt.why = failure->reason + " (" + failure->where() + ")";
  attempt.ok = false;
}

void LoadStepper::commit(const std::vector<double> &nextMultipliers) {
  const StepTrial &trial = *trial_;
  if (extrapolate_) {
    previous_->assign(*committed_);
    previousDt_ = trial.dt;
  }
  committed_->assign(trial.state);
  multipliers_.commit(nextMultipliers, trial.dt);
  t_ = trial.time;
  ++stepNumber_;
  steps_.accept();
}

StepTrial &LoadStepper::beginTrial(double time, double assemblySeconds) {
  trial_ = std::make_unique<StepTrial>(time, time - t_, assemblySeconds, *committed_);
  return *trial_;
}

void LoadStepper::save(nlohmann::json &part, nlohmann::json &run) const {
  part["u"] = ownedValues(committed_->u);
  part["lambda"] = committed_->lambda;
  if (extrapolate_) {
    part["previous_u"] = ownedValues(previous_->u);
    part["previous_lambda"] = previous_->lambda;
  }
  part["multiplier_prediction"] = multipliers_.toJson();
  run["step"] = stepNumber_;
  run["time"] = t_;
  run["previous_dt"] = previousDt_;
  const StepSizeController::State steps = steps_.state();
  run["step_size"] = {steps.stepSize, steps.successes};
}

void LoadStepper::restore(const nlohmann::json &part, const nlohmann::json &run) {
  assignOwnedValues(committed_->u, part.at("u"), "displacement");
  committed_->lambda = elementValues(part.at("lambda"), committed_->lambda.size(), "multipliers");
  if (extrapolate_) {
    assignOwnedValues(previous_->u, part.at("previous_u"), "previous displacement");
    previous_->lambda = elementValues(part.at("previous_lambda"), previous_->lambda.size(), "previous multipliers");
  }
  // A checkpoint written before the prediction existed has none: that run's next step starts
  // from its committed multipliers.
  if (part.contains("multiplier_prediction"))
    multipliers_.restore(part.at("multiplier_prediction"), committed_->lambda.size());
  stepNumber_ = run.at("step").get<int>();
  t_ = run.at("time").get<double>();
  previousDt_ = run.at("previous_dt").get<double>();
  steps_.restore({run.at("step_size").at(0).get<double>(), run.at("step_size").at(1).get<int>()});
}

} // namespace glossa::solvers
