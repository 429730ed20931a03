#pragma once
// What a load step moves between and what one attempt at it reports: a state (displacement and
// element multipliers), the outcome of a step solve with its acceptance checks, and the trial of
// a step being attempted from the committed state.

#include <chrono>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "assembly/MuscleResponse.hpp"
#include "assembly/TpetraTypes.hpp"
#include "solvers/control/ControlStepResult.hpp"
#include "solvers/nonlinear/SolveStatistics.hpp"
#include "solvers/run/AirflowStep.hpp"

namespace glossa::solvers {

// A displacement and its element multipliers (Lambda_e per local element).
struct StepState {
  StepState(const Teuchos::RCP<const assembly::Map> &map, std::size_t elements) : u(map), lambda(elements, 0.0) {}
  StepState(const StepState &from) : u(from.u, Teuchos::Copy), lambda(from.lambda) {}
  StepState &operator=(const StepState &) = delete;
  void assign(const StepState &from) {
    u.assign(from.u);
    lambda = from.lambda;
  }
  assembly::Vector u;
  std::vector<double> lambda;
};

// One step solve's outcome and the checks of its converged state.
struct StepAttempt {
  UzawaResult uzawa;
  assembly::MuscleFields muscle;
  bool ok = false;
  std::string why;
  double minCornerJ = 1.0;          // the smallest corner det F of the converged state
  mesh::ElementId cornerElement = 0; // where
  double minRegularCornerJ = 1.0;   // the same over regular corners (ResultEvaluator::WorstCorner)
  mesh::ElementId regularCornerElement = 0;
  double turnedOver = 0.0;          // the largest fraction of an element turned over (fem::turnedOverFraction)
  nlohmann::json folded;            // converged with an element folded: which, where (StepSolver::measureCorners)
  double pathStiffness = std::numeric_limits<double>::quiet_NaN(); // S (LimitPointMonitor); NaN: not measured
  bool unstable = false;            // converged, but past a limit point (S <= 0)
  nlohmann::json insideOut;         // converged inside out: where (model/SymmetryPlanes.hpp)
  AirflowStep airflow;              // a scene with airflow: the coupling (its solves' counts summed in `uzawa`)
  double loadScale = 0.0;           // [N] what the Newton tolerance was relative to (StepSolver::solve)
};

// The step being attempted: to `time` by `dt`, its state the start on entry and the trial state
// after the attempt.
struct StepTrial {
  using Clock = std::chrono::steady_clock;
  StepTrial(double time, double dt, double assemblyAtStart, const StepState &start)
      : time(time), dt(dt), start(Clock::now()), assemblyAtStart(assemblyAtStart), state(start) {}
  double time, dt;
  Clock::time_point start;
  double assemblyAtStart; // the model's assembly seconds when the attempt began
  StepState state;
  StepAttempt attempt;
  ControlStepResult control; // a controlled step's
};

} // namespace glossa::solvers
