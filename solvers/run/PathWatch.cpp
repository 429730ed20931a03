#include "solvers/run/PathWatch.hpp"

#include <cmath>
#include <cstdio>

#include "assembly/Assembler.hpp"
#include "assembly/ModelEvaluator.hpp"
#include "assembly/ResultEvaluator.hpp"
#include "solvers/incompressibility/Augmentation.hpp"
#include "solvers/incompressibility/ConstrainedTangent.hpp"
#include "solvers/nonlinear/NewtonSolver.hpp"
#include "solvers/stepping/LimitPointMonitor.hpp"
#include "solvers/stepping/PathStiffness.hpp"

namespace glossa::solvers {

LargestMotion largestMotion(const assembly::ResultEvaluator &results, const assembly::Vector &v) {
  const std::vector<double> all = results.gatherDisplacement(v);
  LargestMotion best;
  double largest = -1.0;
  for (std::size_t n = 0; 3 * n + 2 < all.size(); ++n) {
    const double m = Eigen::Vector3d(all[3 * n], all[3 * n + 1], all[3 * n + 2]).squaredNorm();
    if (m > largest) largest = m, best.node = n;
  }
  best.norm = std::sqrt(std::max(largest, 0.0));
  return best;
}

PathWatch::PathWatch(const assembly::Assembler &assembler, assembly::ModelEvaluator &model, const NewtonSolver &newton,
                     double nominalStep, double tolerance, bool talk, Augmentation *augmentation)
    : assembler_(assembler), model_(model), newton_(newton),
      limit_(std::make_unique<LimitPointMonitor>(nominalStep, tolerance)), talk_(talk), augmentation_(augmentation) {}

PathWatch::~PathWatch() = default;

void PathWatch::check(StepTrial &trial) {
  model_.setTime(trial.time);
  model_.setMultipliers(trial.state.lambda);
  PathStiffness measured = pathStiffness(assembler_, newton_, trial.state.u, trial.time, trial.dt, trial.state.lambda);
  StepAttempt &a = trial.attempt;
  a.pathStiffness = limit_->relativeStiffness(measured.stiffness);
  // Far from a limit point the two tangents tell the same (S of order 1 either way); near one,
  // only the constrained problem's says where its maximum is. Not measured at all (df/dt = 0): nothing to redo.
  const bool unmeasurable = std::isnan(measured.stiffness) && measured.note.empty();
  if (augmentation_ && !(a.pathStiffness >= LimitPointMonitor::kSoftened) && !unmeasurable) {
    {
      const ConstrainedTangent constrained(*augmentation_, assembly::ResultEvaluator(assembler_), trial.state.u,
                                           trial.state.lambda);
      model_.setMultipliers(constrained.multipliers());
      measured = pathStiffness(assembler_, newton_, trial.state.u, trial.time, trial.dt, constrained.multipliers(),
                               /*ownSolver=*/true);
    }
    model_.setMultipliers(trial.state.lambda);
    a.pathStiffness = limit_->relativeStiffness(measured.stiffness);
  }
  if (!measured.note.empty() && talk_)
    std::printf("  note: the stiffness along the path at t = %.6g was not measured: %s\n", trial.time, measured.note.c_str());
  if (!LimitPointMonitor::beyond(a.pathStiffness)) return;
  a.ok = false;
  a.unstable = true;
  char why[200];
  std::snprintf(why, sizeof why,
                "the converged state is past a limit point (the tangent's stiffness along the path is %.3g of the "
                "first step's: an unstable equilibrium)", a.pathStiffness);
  a.why = why;
}

void PathWatch::accepted(double t, double pathStiffness) {
  limit_->accepted(t, pathStiffness);
  if (!(pathStiffness < LimitPointMonitor::kSoftened) || softeningSaid_) return;
  softeningSaid_ = true;
  if (talk_)
    std::printf("  note: the load path has softened: the tangent's stiffness along the path is %.3g of the first "
                "step's (a limit point may be near)\n", pathStiffness);
  // The Newton solves at fixed multipliers find no state past the inner problem's own maximum,
  // which lies about 10 mu / kappa_AL below the constrained one (the thick sphere: 0.3 % at 30 mu):
  // past it every step would fail, and the failures would bracket the wrong maximum.
  for (std::size_t tissue = 0; augmentation_ && tissue < augmentation_->tissues(); ++tissue) {
    if (!(augmentation_->ratios()[tissue] < kNearLimitPointRatio)) continue;
    augmentation_->setRatio(tissue, kNearLimitPointRatio);
    if (talk_)
      std::printf("  note: kappa_AL raised to %.3g mu in tissue %zu for the rest of the run, so that the Newton solves "
                  "at fixed multipliers reach the limit point\n", kNearLimitPointRatio, tissue);
  }
}

PathWatch::Verdict PathWatch::refused(double t, const StepTrial &trial, const StepState &committed, double nextStep,
                                      bool stepLeft) {
  // Where it moves most: along the unstable step, or (Newton found nothing) in all so far.
  assembly::Vector motion(trial.state.u, Teuchos::Copy);
  if (trial.attempt.unstable) motion.update(-1.0, committed.u, 1.0);
  else motion.assign(committed.u);
  limit_->refused(t, trial.time, trial.attempt.unstable, largestMotion(assembly::ResultEvaluator(assembler_), motion).node);
  Verdict v;
  v.located = limit_->located(nextStep) || (!stepLeft && limit_->located(0.0));
  if (!v.located) return v;
  const Eigen::Vector3d x = assembler_.scene().mesh.nodes[limit_->node()];
  v.record = limit_->record(x);
  v.description = limit_->description(x);
  return v;
}

nlohmann::json PathWatch::state() const {
  return {{"limit_point", limit_->state()}, {"softening_said", softeningSaid_}};
}

void PathWatch::restore(const nlohmann::json &run) {
  if (run.contains("limit_point")) limit_->restore(run.at("limit_point"));
  softeningSaid_ = run.at("softening_said").get<bool>();
}

} // namespace glossa::solvers
