#include "solvers/incompressibility/UzawaLoop.hpp"

#include <algorithm>
#include <cmath>

#include <Teuchos_CommHelpers.hpp>

#include "io/deck/DeckError.hpp"

namespace glossa::solvers {

double UzawaLoop::augmentationKappa(const IncompressibilityParameters &p, double mu) {
  return p.penaltyRatio * mu;
}

double UzawaLoop::tangentKappa(const IncompressibilityParameters &s, double materialKappa, double mu) {
  // Mixed: the kernel carries no volumetric energy; the pressure unknowns carry the law.
  if (s.method == IncompressibilityMethod::mixed) return 0.0;
  if (s.method == IncompressibilityMethod::augmentedLagrangian)
    return AugmentedLagrangianRule(materials::VolumetricEnergy(materials::VolumetricEnergy::Form::Quadratic, materialKappa),
                                   augmentationKappa(s, mu))
        .tangentKappa();
  if (!std::isfinite(materialKappa))
    throw io::DeckError("Material: an infinite bulk modulus (Poisson's ratio = 0.5, exact incompressibility) "
                        "needs Incompressibility/method = augmented Lagrangian or mixed; a penalty needs nu < 0.5");
  return materialKappa;
}

UzawaLoop::UzawaLoop(const assembly::ResultEvaluator &results, const NewtonSolver &newton,
                     const IncompressibilityParameters &s, const std::vector<materials::VolumetricEnergy> &physical)
    : results_(results), newton_(newton), augmented_(s.method == IncompressibilityMethod::augmentedLagrangian),
      mixed_(s.method == IncompressibilityMethod::mixed), tolerance_(s.dilatationTolerance),
      maxIterations_(s.maximumUzawaIterations), inexact_(augmented_ && s.inexactUzawa),
      innerTolerance_(s.innerTolerance), innerLinearTolerance_(s.innerLinearTolerance) {
  const model::Scene &scene = results.scene();
  physical_ = physical;
  for (std::size_t t = 0; t < scene.tissues.size(); ++t) {
    mu_.push_back(scene.tissues[t].matrix->shearModulus());
    ratio_.push_back(s.penaltyRatio);
    rules_.emplace_back(physical.at(t), ratio_.back() * mu_.back());
  }
  for (const auto e : results.assembler().layout().localElements)
    localTissue_.push_back(scene.elementTissue.empty() ? 0 : scene.elementTissue[static_cast<std::size_t>(e)]);
}

std::vector<double> UzawaLoop::penaltyRatios() const { return ratio_; }

std::vector<double> UzawaLoop::tissueErrors(const assembly::ElementFields &f) const {
  std::vector<double> local(rules_.size(), 0.0), global(rules_.size(), 0.0);
  for (std::size_t i = 0; i < f.theta.size(); ++i)
    local[localTissue_[i]] = std::max(local[localTissue_[i]], ruleOf(i).dilatationError(f.theta[i], f.pressure[i]));
  Teuchos::reduceAll(*results_.assembler().layout().comm(), Teuchos::REDUCE_MAX, static_cast<int>(local.size()),
                     local.data(), global.data());
  return global;
}

std::vector<int> UzawaLoop::activeTissues() const {
  const model::Scene &scene = results_.scene();
  const model::MuscleHistory &history = results_.muscleHistory();
  std::vector<int> local(rules_.size(), 0), global(rules_.size(), 0);
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
  for (std::size_t t = 0; t < rules_.size(); ++t) {
    if (!active[t]) continue;
    if (!(errors[t] > tolerance_) || !(errors[t] > kSlowContraction * previous[t])) continue;
    if (ratio_[t] * kAugmentationGrowth > kMaximumPenaltyRatio) continue;
    ratio_[t] *= kAugmentationGrowth;
    rules_[t] = AugmentedLagrangianRule(physical_[t], ratio_[t] * mu_[t]);
    if (onRaise_) onRaise_(t, rules_[t].tangentKappa());
    raised = true;
  }
  return raised;
}

void UzawaLoop::restorePenaltyRatios(const std::vector<double> &ratios) {
  if (ratios.size() != ratio_.size())
    throw std::invalid_argument("UzawaLoop::restorePenaltyRatios: " + std::to_string(ratios.size()) + " ratios for " +
                                std::to_string(ratio_.size()) + " tissues");
  for (std::size_t t = 0; t < ratio_.size(); ++t) {
    if (ratios[t] == ratio_[t]) continue;
    ratio_[t] = ratios[t];
    rules_[t] = AugmentedLagrangianRule(physical_[t], ratio_[t] * mu_[t]);
    if (onRaise_) onRaise_(t, rules_[t].tangentKappa());
  }
}

DilatationError UzawaLoop::dilatationError(const assembly::ElementFields &f) const {
  double local[2] = {0.0, 0.0}, volume = 0.0, maxErr = 0.0, maxChange = 0.0;
  for (std::size_t i = 0; i < f.theta.size(); ++i) {
    const double change = std::abs(f.theta[i] - 1.0);
    const double e = measuresPhysicalLaw() ? ruleOf(i).dilatationError(f.theta[i], f.pressure[i]) : change;
    maxErr = std::max(maxErr, e);
    maxChange = std::max(maxChange, change);
    local[0] += e * f.referenceVolume[i];
    volume += f.referenceVolume[i];
  }
  local[1] = volume;
  double sums[2];
  DilatationError err;
  const auto &comm = *results_.assembler().layout().comm();
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2, local, sums);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, maxErr, Teuchos::outArg(err.max));
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, maxChange, Teuchos::outArg(err.maxVolumeChange));
  err.mean = sums[0] / sums[1];
  return err;
}

UzawaResult UzawaLoop::solve(assembly::Vector &u, std::vector<double> &lambda, double residualTolerance,
                             const NewtonSolver::IterationCallback &onNewton, const UzawaCallback &onUzawa) const {
  return solve(u, lambda, [residualTolerance](double) { return residualTolerance; }, onNewton, onUzawa);
}

UzawaResult UzawaLoop::solve(assembly::Vector &u, std::vector<double> &lambda,
                             const NewtonSolver::ToleranceRule &toleranceRule,
                             const NewtonSolver::IterationCallback &onNewton, const UzawaCallback &onUzawa) const {
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
  bool tight = !inexact_;
  std::vector<double> previousErrors; // after the last tight solve, per tissue
  for (int k = 1; k <= (measuresPhysicalLaw() ? maxIterations_ : 1); ++k) {
    newton_.model().setMultipliers(lambda);
    NewtonResult n = tight ? newton_.solve(u, NewtonSolver::ToleranceRule(tightTolerance), onNewton)
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

    const assembly::ElementFields fields = results_.elementDilatations(u, lambda);
    result.dilatation = dilatationError(fields);
    if (onUzawa) onUzawa(k, result.newton.back(), result.dilatation);
    if (!measuresPhysicalLaw() || result.dilatation.max < tolerance_) {
      if (tight) {
        result.converged = true;
        if (augmented_ && !mixed_) result.nextMultipliers = nextMultipliers(fields);
        return result;
      }
      // The inexact solve meets the tolerance already (its multipliers were well predicted):
      // Newton goes on from its iterate to the full tolerance with them, no update between.
      tight = true;
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
    lambda = nextMultipliers(fields);
  }
  return result;
}

std::vector<double> UzawaLoop::nextMultipliers(const assembly::ElementFields &fields) const {
  std::vector<double> next(fields.pressure.size());
  for (std::size_t i = 0; i < next.size(); ++i) next[i] = ruleOf(i).nextMultiplier(fields.pressure[i]);
  return next;
}

} // namespace glossa::solvers
