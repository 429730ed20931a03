#pragma once
// The load path's watch under load control (Time/at a limit point = stop or follow): the
// tangent's stiffness along each converged step (PathStiffness), a step past a limit point
// refused, the note once the path has softened, and, after refused steps, the limit point
// located between the last accepted and the first refused load (LimitPointMonitor).

#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "solvers/run/StepState.hpp"

namespace glossa::assembly {
class Assembler;
class ModelEvaluator;
class ResultEvaluator;
} // namespace glossa::assembly

namespace glossa::solvers {

class Augmentation;
class LimitPointMonitor;
class NewtonSolver;

class PathWatch {
public:
  // `nominalStep`: the deck's step, the monitor's scale; `tolerance`: Time/limit point tolerance.
  // `augmentation`: with the augmented Lagrangian, the tissues' laws, whose constrained tangent
  // measures the stiffness near a limit point (ConstrainedTangent); null otherwise.
  PathWatch(const assembly::Assembler &assembler, assembly::ModelEvaluator &model, const NewtonSolver &newton,
            double nominalStep, double tolerance, bool talk, Augmentation *augmentation = nullptr);
  ~PathWatch();

  // A converged trial: its stiffness along the step, and the trial refused (unstable) when that
  // is not positive. With the augmented Lagrangian, once the stiffness at fixed multipliers is
  // below LimitPointMonitor::kSoftened it is measured again with the constrained problem's
  // tangent, which decides: the inner problem's own maximum comes first (ConstrainedTangent).
  // Collective.
  void check(StepTrial &trial);
  // A committed step at t: the monitor's history, and the note once the path has softened; with
  // the augmented Lagrangian, each tissue's kappa_AL then raised to kNearLimitPointRatio mu for
  // the rest of the run (the inner problem's maximum 0.03 % below the constrained one's).
  void accepted(double t, double pathStiffness);
  static constexpr double kNearLimitPointRatio = 300.0;

  // After a refused trial from the committed state at t: the monitor learns where it failed;
  // whether the limit point is now located, given the next step (0 if none is left).
  struct Verdict {
    bool located = false;
    nlohmann::json record;   // summary.json's limit_point
    std::string description; // the failure, if the run stops there
  };
  Verdict refused(double t, const StepTrial &trial, const StepState &committed, double nextStep, bool stepLeft);

  nlohmann::json state() const; // for a checkpoint
  void restore(const nlohmann::json &run);

private:
  const assembly::Assembler &assembler_;
  assembly::ModelEvaluator &model_;
  const NewtonSolver &newton_;
  std::unique_ptr<LimitPointMonitor> limit_;
  bool talk_;
  Augmentation *augmentation_;
  bool softeningSaid_ = false; // the note that the path has softened, once
};

// The mesh node with the largest |v| and that |v| (gathered on every rank). Collective.
struct LargestMotion {
  std::size_t node = 0;
  double norm = 0.0;
};
LargestMotion largestMotion(const assembly::ResultEvaluator &results, const assembly::Vector &v);

} // namespace glossa::solvers
