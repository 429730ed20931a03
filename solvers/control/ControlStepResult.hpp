#pragma once
// What a control step decided (doc/control.md): the inputs, which groups were searched, the winner's
// objective and per-point errors, how much the search cost, and the winning solve's statistics.
// It travels among control groups as a flat buffer of doubles (one broadcast from the winning
// group's root), so it serialises to and from one, exactly.

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "solvers/nonlinear/SolveStatistics.hpp"

namespace glossa::solvers {

struct ControlStepResult {
  std::vector<double> inputs;  // per muscle group of the scene (0 if not controlled or pruned)
  std::vector<int> evaluated;  // the groups searched (scene indices), ascending
  double objective = 0.0;      // eq. 25 at the winner; +inf when no candidate converged
  std::size_t candidates = 0;  // full step solves
  int generations = 0;         // GA
  int iterations = 0;          // gradient: accepted Gauss-Newton steps
  int sensitivities = 0;       // gradient: sensitivity evaluations
  int sensitivityKrylov = 0;   // gradient: their Krylov iterations
  double sensitivityCheck = -1.0; // verify sensitivities: max |S - S_fd| / max |S_fd| (-1: not checked)
  std::size_t failedCandidates = 0; // candidate solves that did not converge (all control groups)
  std::size_t screenedCandidates = 0; // of them, GA candidates whose moved start turned an element over
                                      // and that were not solved again (Control/retry turned-over starts)
  std::size_t solvedAgainCandidates = 0;  // moved starts that failed, solved again from the step's start
  std::string firstFailure;    // why the first of them this control group saw failed ("" if none)
  std::string stop;            // why the search stopped
  Eigen::VectorXd pointErrors; // ||x_p - xbar_p|| per control point at the winner
  UzawaResult solve;           // the winning solve's statistics
  int couplingIterations = 0;  // its airflow coupling iterations (doc/airflow.md; 0 without)
  double couplingChange = 0.0; // and its last change of a section's pressure [Pa]

  bool found() const; // a candidate converged (the objective is finite)
};

// Appends `result` to `buffer`; readControlStepResult() reads it back from `position` (advanced
// past it), bit for bit. Throws std::runtime_error if the buffer ends early.
void appendControlStepResult(const ControlStepResult &result, std::vector<double> &buffer);
ControlStepResult readControlStepResult(const std::vector<double> &buffer, std::size_t &position);

} // namespace glossa::solvers
