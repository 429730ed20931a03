#pragma once
// The load stepper: the committed state and the step being attempted from it. It chooses where
// an attempt starts (the committed state, or its linear extrapolation from the step before, the
// multipliers one Uzawa update ahead: MultiplierPredictor), retries once from the committed
// state an attempt that failed from the extrapolated one, commits a converged trial, and cuts the
// step back after a failure. How a step is solved is the StepAttempter's business, so the
// stepper can be tested on a fake solve.

#include <functional>
#include <memory>

#include <nlohmann/json.hpp>

#include "solvers/incompressibility/MultiplierPredictor.hpp"
#include "solvers/run/StepState.hpp"
#include "solvers/stepping/StepSizeController.hpp"

namespace glossa::solvers {

class StepAttempter {
public:
  virtual ~StepAttempter() = default;
  // Solves `trial` (its state holds the start on entry, the trial state after) and sets its
  // attempt's outcome. Collective.
  virtual void attempt(StepTrial &trial) = 0;
};

class LoadStepper {
public:
  // `extrapolate`: the linear predictor (Time/predictor); `initial`: the state at t = 0.
  LoadStepper(const StepSizeRule &rule, bool extrapolate, const StepState &initial);

  double time() const { return t_; } // of the committed state
  int stepNumber() const { return stepNumber_; }
  bool finished() const { return !(t_ < steps_.endTime() * (1.0 - 1e-12)); }
  const StepSizeController &steps() const { return steps_; }
  const StepState &committed() const { return *committed_; }
  // Where every solve of the step being attempted starts (a controller's candidates too).
  const StepState &stepStart() const { return *stepStart_; }
  StepTrial &trial() { return *trial_; }
  const StepTrial &trial() const { return *trial_; }

  // Attempts the next step (of the step-size controller's size) from the committed state or its
  // extrapolation; an attempt that fails from the extrapolated state (and is not past a limit
  // point) is made once more, at the same size, from the committed state, after `onRetry`.
  // `assemblySeconds`: the model's so far, for the step's record. Nothing is committed. Collective.
  bool attemptStep(StepAttempter &attempter, double assemblySeconds, const std::function<void(const StepTrial &)> &onRetry);
  // The converged trial becomes the committed state; `nextMultipliers`: where the step after it
  // would update the multipliers to (empty: no prediction).
  void commit(const std::vector<double> &nextMultipliers);
  // The trial of a point reached otherwise (an arc-length path's), from the committed state.
  StepTrial &beginTrial(double time, double assemblySeconds);
  // After a failed attempt: the next attempt's step is cut back; false if it would fall below
  // the minimum step size.
  bool cutBack() { return steps_.cutBack(); }
  // The next attempt's step, set by the caller (the closing-pressure search's bisection): false
  // if it is below the minimum step size.
  bool setStepSize(double dt) {
    steps_.restore({dt, 0});
    return dt >= steps_.minimumStep();
  }

  // A checkpoint's parts: this rank's states (`part`) and rank 0's scalars (`run`).
  void save(nlohmann::json &part, nlohmann::json &run) const;
  void restore(const nlohmann::json &part, const nlohmann::json &run);

private:
  bool attemptFrom(StepAttempter &attempter, double dt, bool extrapolated, double assemblySeconds);
  // Every rank takes the attempt as failed (and past a limit point) when any rank does. Collective.
  void agreeOnOutcome(StepAttempt &attempt) const;

  StepSizeController steps_;
  bool extrapolate_;
  std::unique_ptr<StepState> committed_, previous_, stepStart_;
  double previousDt_ = 0.0; // the step between previous_ and committed_
  MultiplierPredictor multipliers_;
  double t_ = 0.0;
  int stepNumber_ = 0;
  std::unique_ptr<StepTrial> trial_;
};

} // namespace glossa::solvers
