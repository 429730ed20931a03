#pragma once
// One control step (paper §6.1, doc/control.md): prune the muscle groups by their mean fibre stretch at
// the committed state, search the inputs of the others (the elitist GA or the projected
// Gauss-Newton controller of control/), each candidate a full step solve by the plant from the
// committed state, and, with control groups, share the winner among them. The state of the
// winner is the plant's kept state when step() returns. Knows nothing of decks or Trilinos: the
// solver is behind ControlPlant, the communication behind ControlGroups (doc/control.md).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "control/ControlObjective.hpp"
#include "control/ControllerParameters.hpp"
#include "control/GeneticAlgorithmParameters.hpp"
#include "solvers/control/ControlGroups.hpp"
#include "solvers/control/ControlPlant.hpp"
#include "solvers/control/ControlStepResult.hpp"

namespace glossa::solvers {

struct ControlDriverSetup {
  control::ControllerParameters parameters; // validated
  std::vector<std::string> groupNames;      // every muscle group of the scene
  std::vector<int> controlled;              // the groups the controller drives (scene indices), ascending
  Eigen::Matrix3Xd referencePositions;      // the control points where the displacement is 0
  Eigen::Matrix3Xd goals;                   // xbar_p of eq. 25
  Eigen::VectorXd weights;                  // w_p of eq. 25
  bool talk = false;                        // print the sensitivity check
};

class ControlDriver {
public:
  // `plant` and `groups` must outlive the driver. Throws std::invalid_argument for goals and
  // weights that do not match (ControlObjective).
  ControlDriver(ControlDriverSetup setup, ControlPlant &plant, const ControlGroups &groups);

  // The step after `committedSteps` committed ones; `committedStretch`: every group's mean fibre
  // stretch at the committed state. The GA's seed is offset by `committedSteps` (fresh draws per
  // step); both controllers start from the inputs of the last step whose result was found.
  // Collective over all control groups.
  ControlStepResult step(int committedSteps, const std::vector<double> &committedStretch);

  // The groups a step searches (scene indices, ascending): the controlled ones in tension, those
  // always evaluated and (keep active groups) those the last found step switched on.
  std::vector<int> evaluatedGroups(const std::vector<double> &committedStretch) const;

  // x_p = X_p + d_p: where the control points are, from their displacement.
  Eigen::Matrix3Xd positions(const Eigen::Matrix3Xd &pointDisplacement) const;

  // What a checkpoint keeps: the inputs of the last two found steps (both controllers start from
  // them). The GA's random stream needs nothing more: it is seeded afresh every step from the
  // parameters' seed and the number of committed steps.
  std::pair<control::Genome, control::Genome> memory() const { return {previousBest_, olderBest_}; }
  void restoreMemory(const std::pair<control::Genome, control::Genome> &m) { previousBest_ = m.first, olderBest_ = m.second; }

private:
  struct Search; // the step's result so far, with the rank of its best candidate

  // Every muscle group's input from inputs over the evaluated groups (the others 0).
  std::vector<double> allInputs(const std::vector<int> &evaluated, const Eigen::VectorXd &v) const;
  control::ControlEvaluation solveCandidate(Search &search, const std::vector<double> &inputs, bool rankByObjective,
                                            long index);
  void searchGenetic(Search &search, int committedSteps, const std::vector<double> &previousInputs);
  void searchGradient(Search &search, const std::vector<double> &previousInputs);
  // S = dr/du at the kept state, rows weighted as the residual; checked against differences of
  // full solves when the parameters ask.
  Eigen::MatrixXd weightedSensitivity(Search &search);
  double differenceCheck(const InputSensitivity &s, const Search &search);
  void shareWinner(Search &search);
  // epsilon sum_M u_M^2 (ControllerParameters::effortWeight).
  double effort(const std::vector<double> &inputs) const;
  // The airway term w_A max(0, A_open - A) [m] at a candidate's smallest lumen area A (0 without
  // the term or without a measured area).
  bool hasAirwayTerm() const;
  double airwayTerm(double smallestArea) const;
  // The GA's seeds: the previous step's best and the prediction the parameters ask for.
  std::vector<control::Genome> geneticSeeds(Search &search, const std::vector<double> &previousInputs);
  // The inputs one bounded Gauss-Newton step from `from`, linearised there, at the step lengths
  // 1, 1/2, ... of ControllerParameters::predictionSeedSteps (the solve at `from` is a candidate
  // like any other).
  std::vector<std::vector<double>> gaussNewtonPrediction(Search &search, const std::vector<double> &from);

  ControlDriverSetup setup_;
  ControlPlant &plant_;
  const ControlGroups &groups_;
  control::ControlObjective objective_;
  control::Genome previousBest_; // per controlled group: the inputs of the last found step
  control::Genome olderBest_;    // the same for the found step before it (the prediction's second point)
};

} // namespace glossa::solvers
