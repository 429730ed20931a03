#pragma once
// The controlled step (paper §6.1): the control driver searches the inputs of the controlled
// muscle groups that keep the control points at their goals (eq. 25), each candidate a full
// step solve from where the step starts; the winner's state becomes the step's trial. This is
// the driver's plant (ControlPlant) over the run's step solver, and controls.csv with the
// summary's "control" record of each step.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "solvers/control/ControlDriver.hpp"
#include "solvers/parameters/ControlSection.hpp"
#include "solvers/control/ControlSensitivity.hpp"
#include "solvers/run/CandidateStart.hpp"
#include "solvers/run/StepSolver.hpp"

namespace glossa::io {
class KeyedCsvWriter;
}
namespace glossa::model {
struct AirwayOutput;
}

namespace glossa::solvers {

class Augmentation;
class CommControlGroups;
class LoadStepper;

class ControlledSteps final : public ControlPlant {
public:
  // `resumeControlsAt`: a restart's length of controls.csv. `writer`: this rank writes it.
  // `airway`: the deck's lumen, which the controller's airway term measures (null without one).
  // `augmentation`: the augmented Lagrangian's (null without one), whose laws the predicted starts'
  // responses exchange for the constrained ones; `constrainedSensitivity`: the gradient
  // controller's sensitivities do so too (otherwise they take the inner solves' tangent).
  ControlledSteps(const ControlSetup &setup, const StepSolverParts &parts, const StepSolver &solver,
                  const LoadStepper &stepper, const CommControlGroups &groups, const std::filesystem::path &dir,
                  std::optional<std::uintmax_t> resumeControlsAt, bool writer, bool talk,
                  std::shared_ptr<const model::AirwayOutput> airway = nullptr, Augmentation *augmentation = nullptr,
                  bool constrainedSensitivity = false);
  ~ControlledSteps() override;

  // Searches the step's inputs; the winner's state and statistics become `trial`'s. Collective.
  void step(StepTrial &trial, int committedSteps);
  // A committed step's record: controls.csv's rows, the summary's "control" object, and the
  // console's line about it (controlLine()).
  nlohmann::json record(const StepTrial &trial, double t);
  const std::string &controlLine() const { return controlLine_; }
  // The committed step's mean fibre stretch of every group (pruning, §6.1).
  void committed(const StepTrial &trial) { committedStretch_ = trial.attempt.muscle.groupMeanStretch; }
  void setCommittedStretch(const std::vector<double> &stretch) { committedStretch_ = stretch; }

  // A checkpoint's part (rank 0's): the driver's memory and the committed stretches.
  void save(nlohmann::json &run) const;
  void restore(const nlohmann::json &run);
  // How far controls.csv has got (the writer rank's; empty elsewhere), for a checkpoint's mark.
  std::optional<std::uintmax_t> controlsBytes() const;

  // ControlPlant: candidates solved from the step's start.
  CandidateSolve solve(const std::vector<double> &inputs) override;
  void keepLast() override;
  InputSensitivity sensitivity(const std::vector<double> &inputs, const std::vector<int> &groups) override;
  std::vector<double> packKept() const override; // [u of every node (3 per node), Lambda of every element]
  void unpackKept(const std::vector<double> &state) override;

private:
  // The neural inputs of every group over the step: the controller's for the controlled groups,
  // the deck's u(t) for the others (the model evaluator's p2 for the step).
  std::vector<double> stepInputs(const std::vector<double> &inputs, double time) const;
  // The control points' displacement (one column per point) from every node's (gathered).
  Eigen::Matrix3Xd pointDisplacement(const std::vector<double> &uAll) const;
  // The airway term's: the lumen at every node's displacement `uAll`, and the area of its section
  // `section` (-1: the smallest; NaN when that section is not measured).
  double lumenArea(const std::vector<double> &uAll, int section = -1) const;
  // The controller's airway term is on: candidates and sensitivities measure the lumen.
  bool measuresLumen() const { return airway_ && setup_.parameters.airwayWeight > 0.0; }

  const ControlSetup &setup_;
  StepSolverParts parts_;
  const StepSolver &solver_;
  const LoadStepper &stepper_;
  StepState last_, kept_;
  // Where the next candidate starts (ControllerParameters::predictedStart). The gradient
  // controller's: the kept state moved along its sensitivities (start_). The GA's: the state of
  // its Gauss-Newton seed's solve (seed_), which every control group solves alike, moved along
  // that state's constrained responses (seedStart_), so that the groups still agree.
  double lastLoadScale_ = 0.0, keptLoadScale_ = 0.0; // StepAttempt::loadScale of the last solve, of the kept one
  CandidateStart start_, seedStart_;
  StepState seed_;
  double seedLoadScale_ = 0.0;
  Augmentation *augmentation_ = nullptr; // the augmented Lagrangian's volumetric laws (null: none)
  bool constrainedSensitivity_ = false;  // the gradient controller's sensitivities take them
  // The sensitivity at the kept state, with the physical bulk modulus capped at the parameters'
  // ratio (ConstrainedTangent) when `constrained`; records `start`'s prediction when asked.
  ControlPointSensitivity keptSensitivity(const std::vector<double> &inputs, const std::vector<int> &groups,
                                          bool constrained, CandidateStart *start);
  // The controller's sensitivity at the kept state, recording where later candidates start.
  ControlPointSensitivity controllerSensitivity(const std::vector<double> &inputs, const std::vector<int> &groups);
  // What became of a candidate's moved start (CandidateSolve's flags of the same names).
  struct StartOutcome {
    bool screened = false;     // it turned an element over and the candidate was not solved again
    bool solvedAgain = false;  // it failed and the candidate was solved again from the step's start
  };
  // Solves a candidate from `from` moved by `start` to `inputs`, then, should that fail, from the
  // step's start (both solves counted); not when the moved start converged to a state with an
  // element folded through itself, nor when it turned an element over and
  // screensTurnedOverStarts() (the candidate fails; `outcome.screened` says so).
  StepAttempt solveFrom(const std::vector<double> &inputs, const StepState *from, const CandidateStart *start,
                        double loadScale, StartOutcome &outcome);
  // The GA with Control/retry turned-over starts = false.
  bool screensTurnedOverStarts() const;
  std::shared_ptr<const model::AirwayOutput> airway_;
  std::unique_ptr<ControlDriver> driver_;
  std::unique_ptr<io::KeyedCsvWriter> controls_;
  std::vector<double> committedStretch_;
  std::string controlLine_; // the last control step's summary, for its step's line
};

} // namespace glossa::solvers
