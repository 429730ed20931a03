#include "solvers/incompressibility/UzawaLoop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include <Teuchos_CommHelpers.hpp>

#include "assembly/ContactResponse.hpp"
#include "assembly/RankAgreement.hpp"
#include "assembly/TimeSplit.hpp"

#include <stdexcept>
#include <string>

namespace glossa::solvers {

UzawaLoop::UzawaLoop(const assembly::ResultEvaluator &results, const NewtonSolver &newton,
                     const IncompressibilityParameters &s, Augmentation &augmentation)
    : results_(results), newton_(newton), augmented_(s.method == IncompressibilityMethod::augmentedLagrangian),
      mixed_(s.method == IncompressibilityMethod::mixed), augmentation_(augmentation), tolerance_(s.dilatationTolerance),
      maxIterations_(s.maximumUzawaIterations), inexact_(augmented_ && s.inexactUzawa),
      innerTolerance_(s.innerTolerance), innerLinearTolerance_(s.innerLinearTolerance),
      acceleration_(s.multiplierAcceleration), andersonDepth_(s.andersonDepth) {
  const model::Scene &scene = results.scene();
  if (augmentation.tissues() != scene.tissues.size())
    throw std::invalid_argument("UzawaLoop: an augmentation of " + std::to_string(augmentation.tissues()) +
                                " tissues for a scene of " + std::to_string(scene.tissues.size()));
  for (const auto &contact : scene.contacts) augmentedContact_ = augmentedContact_ || contact.augmented();
  for (const auto e : results.assembler().layout().localElements)
    localTissue_.push_back(scene.elementTissue.empty() ? 0 : scene.elementTissue[static_cast<std::size_t>(e)]);
}

std::vector<double> UzawaLoop::tissueErrors(const assembly::ElementFields &f) const {
  // A NaN stays (std::max would drop it on some ranks only): the ranks decide alike whether to
  // raise a tissue's kappa_AL.
  std::vector<double> local(augmentation_.tissues(), 0.0);
  for (std::size_t i = 0; i < f.theta.size(); ++i) {
    const double e = ruleOf(i).dilatationError(f.theta[i], f.pressure[i]);
    double &worst = local[localTissue_[i]];
    if (std::isnan(e) || e > worst) worst = e;
  }
  return assembly::largestOnAnyRank(*results_.assembler().layout().comm(), local);
}

std::vector<int> UzawaLoop::activeTissues() const {
  const model::Scene &scene = results_.scene();
  const model::MuscleHistory &history = results_.muscleHistory();
  std::vector<int> local(augmentation_.tissues(), 0), global(augmentation_.tissues(), 0);
  const assembly::DistributedLayout &layout = results_.assembler().layout();
  const auto &elements = layout.localElements;
  for (std::size_t i = 0; i < elements.size() && scene.muscles.hasFibres(); ++i) {
    const int region = scene.muscles.elementRegion[static_cast<std::size_t>(elements[i])];
    if (region < 0) continue;
    for (int g : scene.muscles.regions[static_cast<std::size_t>(region)].familyGroup)
      if (history.groupActivation(g) > 0.0) local[localTissue_[i]] = 1;
  }
  Teuchos::reduceAll(*layout.comm(), Teuchos::REDUCE_MAX, static_cast<int>(local.size()), local.data(), global.data());
  return global;
}

bool UzawaLoop::raiseSlowTissues(const std::vector<double> &errors, const std::vector<double> &previous) const {
  bool raised = false;
  const std::vector<int> active = activeTissues();
  for (std::size_t t = 0; t < augmentation_.tissues(); ++t) {
    if (!active[t]) continue;
    if (!(errors[t] > tolerance_) || !(errors[t] > kSlowContraction * previous[t])) continue;
    const double ratio = augmentation_.ratios()[t];
    if (ratio * kAugmentationGrowth > kMaximumPenaltyRatio) continue;
    augmentation_.setRatio(t, ratio * kAugmentationGrowth);
    raised = true;
  }
  return raised;
}

void UzawaLoop::restorePenaltyRatios(const std::vector<double> &ratios) {
  if (ratios.size() != augmentation_.tissues())
    throw std::invalid_argument("UzawaLoop::restorePenaltyRatios: " + std::to_string(ratios.size()) + " ratios for " +
                                std::to_string(augmentation_.tissues()) + " tissues");
  for (std::size_t t = 0; t < ratios.size(); ++t)
    if (ratios[t] != augmentation_.ratios()[t]) augmentation_.setRatio(t, ratios[t]);
}

DilatationError UzawaLoop::dilatationError(const assembly::ElementFields &f) const {
  double local[2] = {0.0, 0.0}, volume = 0.0, maxErr = 0.0, maxChange = 0.0;
  for (std::size_t i = 0; i < f.theta.size(); ++i) {
    const double change = std::abs(f.theta[i] - 1.0);
    const double e = measuresPhysicalLaw() ? ruleOf(i).dilatationError(f.theta[i], f.pressure[i]) : change;
    // A NaN is kept: the convergence test (max < tolerance) then fails on every rank.
    if (std::isnan(e) || e > maxErr) maxErr = e;
    if (std::isnan(change) || change > maxChange) maxChange = change;
    local[0] += e * f.referenceVolume[i];
    volume += f.referenceVolume[i];
  }
  local[1] = volume;
  double sums[2];
  DilatationError err;
  const auto &comm = *results_.assembler().layout().comm();
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2, local, sums);
  const std::vector<double> largest = assembly::largestOnAnyRank(comm, {maxErr, maxChange});
  err.max = largest[0];
  err.maxVolumeChange = largest[1];
  err.mean = sums[0] / sums[1];
  return err;
}

UzawaResult UzawaLoop::solve(assembly::Vector &u, std::vector<double> &lambda, double residualTolerance,
                             const NewtonSolver::IterationCallback &onNewton, const UzawaCallback &onUzawa) const {
  return solve(u, lambda, [residualTolerance](double) { return residualTolerance; }, onNewton, onUzawa);
}

UzawaResult UzawaLoop::solve(assembly::Vector &u, std::vector<double> &lambda,
                             const NewtonSolver::ToleranceRule &toleranceRule,
                             const NewtonSolver::IterationCallback &onNewton, const UzawaCallback &onUzawa,
                             const OuterCondition &outer) const {
  UzawaResult result;
  // The tight tolerance, fixed by the first solve's initial residual. Inexact: while the
  // multipliers are still far from their fixed point, solving each Newton problem to 1e-8 is
  // wasted (the next update changes the problem by more than that); the loose residual tolerance
  // is relative to the same load scale as the tight one.
  double residualTolerance = -1.0;
  auto tightTolerance = [&](double initialNorm) {
    if (residualTolerance < 0.0) residualTolerance = toleranceRule(initialNorm);
    return residualTolerance;
  };
  auto looseTolerance = [&](double initialNorm) {
    const double t = tightTolerance(initialNorm);
    return std::max(t, t * innerTolerance_ / newton_.relativeResidualTolerance());
  };
  bool tight = !inexact_, continuing = false; // continuing: the next solve tightens the last, nothing moved
  std::vector<double> previousErrors; // after the last tight solve, per tissue
  // Anderson's history of this loop's multiplier updates (none: plain updates), and the
  // dilatation error after the last solve that fed it.
  std::optional<AndersonAcceleration> anderson = multiplierAcceleration();
  double lastFedError = std::numeric_limits<double>::infinity();
  for (int k = 1; k <= (measuresPhysicalLaw() || augmentedContact_ || outer ? maxIterations_ : 1); ++k) {
    newton_.model().setMultipliers(lambda);
    NewtonResult n = tight ? newton_.solve(u, tightTolerance, onNewton, std::exchange(continuing, false))
                           : newton_.solveToResidual(u, NewtonSolver::ToleranceRule(looseTolerance), onNewton,
                                                     innerLinearTolerance_);
    // Mixed: the element pressures were unknowns of the solve.
    if (mixed_) lambda = newton_.model().multipliers();
    ++result.solves;
    result.newtonIterations += n.iterations;
    result.linearIterations += n.linearIterations;
    result.elementInverted = n.elementInverted;
    const bool newtonConverged = n.converged;
    result.newton.push_back(std::move(n));
    if (!newtonConverged) return result;

    std::optional<assembly::PartTimer> updateTimer(assembly::TimedPart::uzawaUpdate);
    const assembly::ElementFields fields = results_.elementDilatations(u, lambda);
    result.dilatation = dilatationError(fields);
    // The contacts' gaps at this solve (recorded in their states) and whether every augmented
    // one is within its gap tolerance: the loop ends when both the volume and the contacts are.
    result.contacts = assembly::updateContactStates(results_, u);
    const bool gapMet = result.gapMet();
    updateTimer.reset(); // the callback records the solve: not the update's cost
    if (onUzawa) onUzawa(k, result.newton.back(), result.dilatation, result.contacts);
    const bool volumeMet = !measuresPhysicalLaw() || result.dilatation.max < tolerance_;
    const OuterVerdict outerVerdict = outer ? outer(u) : OuterVerdict::met;
    if (outerVerdict == OuterVerdict::failed) {
      result.outerFailed = true;
      return result;
    }
    // Other loads or contact multipliers: another map, whose history Anderson's would mix in.
    if (anderson && outerVerdict == OuterVerdict::updated) anderson->reset();
    if (outerVerdict == OuterVerdict::updated && volumeMet && gapMet) {
      // Only the outer condition's loads moved: the next solve is tight. Loose solves while the
      // loads move (as for the multipliers' first update) were measured on the supine tongue's
      // airflow and gained nothing: the coupling then took 70 iterations instead of 43 over the 8
      // coupled steps, its map blurred by the loose solves' error, for 113 Newton iterations
      // instead of 120.
      tight = true;
      continue;
    }
    if (volumeMet && gapMet) {
      if (tight) {
        result.converged = true;
        if (augmented_ && !mixed_) result.nextMultipliers = nextMultipliers(fields);
        return result;
      }
      // The inexact solve meets the tolerance already (its multipliers were well predicted):
      // Newton goes on from its iterate to the full tolerance with them, no update between.
      tight = true;
      continuing = true;
      continue;
    }
    // lambda_q <- max(0, lambda_q - eps g_q) at the recorded gaps, beside the volume update: each
    // multiplier takes the pressure its point carried, so the next solve needs less penetration.
    if (!gapMet && assembly::updateContactMultipliers(results_.scene(), result.contacts)) {
      ++result.contactUpdates;
      if (anderson) anderson->reset();
    }
    if (volumeMet) {
      tight = true; // only the contacts move: the volume multipliers stay where they satisfy the law
      continue;
    }
    // A loose solve's error says nothing of the contraction; two tight ones in a row do.
    if (augmented_ && allowRaises_) {
      std::vector<double> errors = tissueErrors(fields);
      if (tight && k >= kSlowSolves && !previousErrors.empty() && raiseSlowTissues(errors, previousErrors))
        ++result.augmentationRaises;
      if (tight) previousErrors = std::move(errors);
    }
    // Only the first solve of a step is loose: its multipliers are the previous step's, so the
    // update changes the problem by more than the tight solve would gain. Later solves are tight:
    // a loose solve's own error puts a floor under the dilatation error it can reach (measured:
    // repeated loose solves stalled above a 1e-9 tolerance and the step failed).
    tight = true;
    // Mixed: the Newton iterates moved the pressures with the displacements; a dilatation error
    // above the tolerance after a converged solve (a loose residual tolerance) only asks for more
    // Newton iterations from here.
    if (mixed_) continue;
    // Lambda_e <- beta p_e (p_e = U_t'(theta_e) + Lambda_e; for nu = 0.5, beta = 1 and this is
    // Lambda_e + kappa_AL (theta_e - 1) to first order): the multiplier takes over the element
    // pressure, so the next solve needs less volume change to carry it (AugmentedLagrangianRule).
    if (!anderson) {
      lambda = nextMultipliers(fields);
      continue;
    }
    // The loose first solve feeds the history too: its iterate is u(lambda) only to 1e-2 of the
    // load, but the secant it gives is good enough to start from (supine gradient deck to 2.5 s:
    // 220 factorisations against 272 without it and 359 with plain updates). An accelerated update
    // that did not lower the error restarts the history (a plain step from here).
    if (!(result.dilatation.max < lastFedError)) anderson->reset();
    lastFedError = result.dilatation.max;
    lambda = anderson->next(lambda, nextMultipliers(fields));
  }
  return result;
}

std::optional<AndersonAcceleration> UzawaLoop::multiplierAcceleration() const {
  if (!accelerates()) return std::nullopt;
  return AndersonAcceleration(andersonDepth_, [comm = results_.assembler().layout().comm()](double *values, int count) {
    std::vector<double> local(values, values + count);
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, count, local.data(), values);
  });
}

std::vector<double> UzawaLoop::nextMultipliers(const assembly::ElementFields &fields) const {
  const assembly::PartTimer timer(assembly::TimedPart::uzawaUpdate);
  std::vector<double> next(fields.pressure.size());
  for (std::size_t i = 0; i < next.size(); ++i) next[i] = ruleOf(i).nextMultiplier(fields.pressure[i]);
  return next;
}

} // namespace glossa::solvers
