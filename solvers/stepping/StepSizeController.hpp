#pragma once
// The step-size rule of quasi-static load/time stepping (doc/theory.md, Time stepping), pure so
// that it is tested without a deck:
// - a failed step is retried from the last committed state with half the step, until the step
//   would fall below the minimum (the run then stops and says why);
// - after two successes in a row the step doubles, up to the nominal step, so a cut-back is
//   recovered in 2 log2(nominal / cut) steps once the steps are easy again;
// - the last step lands exactly on the end time (a remainder within 0.01 % of a step is taken
//   with it, not left as a sliver of round-off).

namespace glossa::solvers {

struct StepSizeRule {
  double endTime = 1.0;
  double nominal = 0.1; // the deck's step, at most the end time
  double minimum = 1e-6;
};

class StepSizeController {
public:
  explicit StepSizeController(const StepSizeRule &rule);

  double endTime() const { return rule_.endTime; }
  // The next step from time t: never past the end time.
  double nextStep(double t) const;
  // After a failure: halve; false if the step would fall below the minimum.
  bool cutBack();
  // After a success: grow back (x2 after two successes in a row) up to the nominal step.
  void accept();
  double stepSize() const { return dt_; }
  double nominalStep() const { return rule_.nominal; }
  double minimumStep() const { return rule_.minimum; }

  // What a checkpoint keeps: the step size and the successes since the last change.
  struct State {
    double stepSize;
    int successes;
  };
  State state() const { return {dt_, successes_}; }
  void restore(const State &s) { dt_ = s.stepSize, successes_ = s.successes; }

private:
  StepSizeRule rule_;
  double dt_;
  int successes_ = 0;
};

} // namespace glossa::solvers
