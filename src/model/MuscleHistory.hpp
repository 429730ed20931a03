#pragma once
// The history of the active muscle on one rank (doc/materials.md, "History"): the activation of every
// muscle group and the contractile stretch lambda_c of every fibre family at every quadrature
// point of the rank's elements, each as a committed value and a trial value.
//
// A step begins from the committed state: beginStep() computes the trial activation by backward
// Euler (eq. 24) from the committed one and u(t_new); the Newton iterations evaluate the point
// law with the committed lambda_c (they never write history); when the step converges the caller
// writes the trial lambda_c at the converged displacement and commits. A failed step simply
// begins again: nothing committed has changed. So a controller may evaluate many candidate
// inputs from one committed state.

#include <cstdint>
#include <vector>

#include "materials/MuscleMaterial.hpp"
#include "mesh/HexMesh.hpp"
#include "model/MuscleArchitecture.hpp"

namespace glossa::model {

class MuscleHistory {
public:
  MuscleHistory() = default;
  // `elements`: the mesh ids of the rank's elements, in its local order.
  MuscleHistory(const MuscleArchitecture &architecture, const std::vector<mesh::ElementId> &elements);

  // Trial activation of every group at tNew = t_committed + dt (dt > 0), from the neural inputs
  // over the step: `inputs` (one per group, clamped to [0, 1]; a controller's, which reach it
  // as the model evaluator's p2), or the deck's u(tNew) when empty.
  void beginStep(double tNew, double dt, const std::vector<double> &inputs = {});
  // The deck's input u(t) of a group, in [0, 1].
  double input(int group, double t) const;

  double dt() const { return dt_; }
  double committedTime() const { return time_; }
  const std::vector<double> &committedActivation() const { return alpha_; }
  const std::vector<double> &trialActivation() const { return alphaTrial_; }
  const std::vector<double> &trialInput() const { return inputTrial_; }

  // Activation per family of local element i (its region's families), from the trial values.
  materials::FamilyValues familyActivation(std::size_t localElement) const;
  // lambda_c of point q of local element i: committed (read) and trial (written).
  const double *committedLambdaC(std::size_t localElement, int q) const;
  double *trialLambdaC(std::size_t localElement, int q);
  int familyCount(std::size_t localElement) const;
  // Where the next local solves for lambda_c of point q start, and where they leave their roots:
  // 3 x familyCount values, the last roots lambda_c, the fibre stretches lambda_f they were found
  // at and d lambda_c / d lambda_f there (materials::MusclePointInput::lambdaCStart). A cache,
  // not state (any start inside the solve's bracket finds the root to its tolerance, 1e-14 of
  // lambda_c), reset by beginStep and restore to the committed lambda_c with no lambda_f (NaN)
  // so that a step's evaluations do not depend on what ran before it (a restart repeats them bit
  // for bit). Within a step lambda_c is a function of lambda_f alone: started from the last root
  // moved along its slope, the local solve takes fewer iterations.
  double *lambdaCStart(std::size_t localElement, int q) const;
  // lambda_c of fibre k of external muscle m (every rank keeps all; the node's owner updates it).
  double committedExternalLambdaC(std::size_t muscle, std::size_t k) const { return externalLambdaC_[muscle][k]; }
  double &trialExternalLambdaC(std::size_t muscle, std::size_t k) { return externalLambdaCTrial_[muscle][k]; }
  // d alpha_trial / d u of a group at this step's input (after beginStep): the controller's
  // sensitivity of the activation to the neural input through the backward-Euler step.
  double trialActivationInputDerivative(int group) const;
  // The trial activation of a group had its input this step been `input` in [0, 1], and its
  // derivative in the input: the activation step from the committed activation over this dt.
  double trialActivationForInput(int group, double input) const;
  double trialActivationInputDerivative(int group, double input) const;
  // Replaces a group's trial activation (finite differences of the residual in alpha); the next
  // beginStep recomputes it from the input.
  void setTrialActivation(int group, double alpha);
  // Trial activation of a group (-1: passive, 0).
  double groupActivation(int group) const { return group < 0 ? 0.0 : alphaTrial_[group]; }

  void commit();
  // The local elements it keeps lambda_c for.
  std::size_t numElements() const { return region_.size(); }

  // The committed state, for a checkpoint (glossa run --restart), and its restoration: the trial
  // values become the committed ones, as after commit().
  struct Snapshot {
    std::vector<double> lambdaC, alpha, input;
    std::vector<std::vector<double>> externalLambdaC;
    double time = 0.0, dt = 1.0;
  };
  Snapshot snapshot() const;
  // Throws std::invalid_argument if its sizes are not this history's (another mesh or partition).
  void restore(const Snapshot &state);

  // Changes whenever what a point law reads here may have changed, other than the trial
  // activation (beginStep, commit, restore): the committed lambda_c, the step size, and the
  // starts of the local solves. What was evaluated under another revision is stale.
  std::uint64_t revision() const { return revision_; }

private:
  const MuscleArchitecture *architecture_ = nullptr;
  std::vector<int> region_;         // per local element
  std::vector<std::size_t> offset_; // per local element: first lambda_c value (8 points x families)
  std::vector<double> lambdaC_, lambdaCTrial_;
  mutable std::vector<double> lambdaCStart_; // 3 x familyCount per point (lambdaCStart)
  std::vector<std::vector<double>> externalLambdaC_, externalLambdaCTrial_;
  std::vector<double> alpha_, alphaTrial_, inputTrial_;
  // dt before the first step: any positive value (the reference state has no rate).
  double time_ = 0.0, dt_ = 1.0, timeTrial_ = 0.0;
  std::uint64_t revision_ = 0;

  void resetLambdaCStarts(); // the committed lambda_c, no lambda_f and slope
};

} // namespace glossa::model
