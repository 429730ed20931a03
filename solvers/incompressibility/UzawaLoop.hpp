#pragma once
// The augmented-Lagrangian loop around each Newton solve (doc/theory.md, eq. 7):
//   solve f(u; Lambda) = 0, then Lambda_e <- beta p_e   (AugmentedLagrangianRule)
// until max_e |theta_e - theta_phys(p_e)| is below the tolerance: the element pressure then obeys
// the material's physical volumetric law (theta -> 1 for nu = 0.5). With a moderate kappa_AL in
// the tangent the Krylov solves stay cheap, while the multiplier carries the pressure that a pure
// penalty would need kappa/mu >= 1e6 to produce. In "penalty" mode the loop performs one solve.
// Contacts enforced by the augmented Lagrangian (doc/contact.md) are updated in the same loop:
// after each converged solve their gaps are recorded, their multipliers updated where the largest
// gap error exceeds the gap tolerance, and the loop ends when both tolerances are met.

#include <functional>
#include <optional>
#include <vector>

#include "assembly/ResultEvaluator.hpp"
#include "solvers/incompressibility/AndersonAcceleration.hpp"
#include "solvers/incompressibility/Augmentation.hpp"
#include "solvers/nonlinear/NewtonSolver.hpp"
#include "solvers/nonlinear/SolveStatistics.hpp"
#include "solvers/parameters/IncompressibilityParameters.hpp"

namespace glossa::solvers {

class UzawaLoop {
public:
  // `results`: of the assembler Newton's model evaluates, for the element dilatations after each
  // solve (kept as a copy: it is a view). `augmentation`: per tissue of its scene, the physical
  // law, kappa_AL and rule, which this loop raises where it contracts slowly (below); it must
  // outlive the loop, and the assembly reads its tangent laws.
  UzawaLoop(const assembly::ResultEvaluator &results, const NewtonSolver &newton,
            const IncompressibilityParameters &parameters, Augmentation &augmentation);

  bool augmentedLagrangian() const { return augmented_; }
  bool mixedPressure() const { return mixed_; }

  // Solves at fixed time; u and lambda are updated in place (the caller keeps copies to roll
  // back). `residualTolerance` is absolute, or given by the norm of the first Newton solve's
  // initial residual (the rule is asked once; every solve of the loop uses its answer).
  // `onUzawa` sees, after each converged Newton solve k, that solve, the dilatation error and the
  // contacts' measures (their gap errors) at it.
  using UzawaCallback = std::function<void(int, const NewtonResult &, const DilatationError &,
                                           const std::vector<contact::ContactMeasures> &)>;
  UzawaResult solve(assembly::Vector &u, std::vector<double> &lambda, double residualTolerance,
                    const NewtonSolver::IterationCallback &onNewton, const UzawaCallback &onUzawa) const;
  // A further condition iterated in the same loop (the airflow's coupling, doc/airflow.md): after
  // every converged Newton solve it is shown the displacement, updates its own loads if it is not
  // met, and says so; the loop ends when it, the volume and the contacts are all met, or when it
  // fails (the loop then returns unconverged, `outerFailed` set).
  enum class OuterVerdict { met, updated, failed };
  using OuterCondition = std::function<OuterVerdict(const assembly::Vector &u)>;
  UzawaResult solve(assembly::Vector &u, std::vector<double> &lambda, const NewtonSolver::ToleranceRule &residualTolerance,
                    const NewtonSolver::IterationCallback &onNewton, const UzawaCallback &onUzawa,
                    const OuterCondition &outer = {}) const;

  DilatationError dilatationError(const assembly::ElementFields &fields) const;
  // The multipliers the next update would set from these element fields, beta p_e per local
  // element (augmented Lagrangian).
  std::vector<double> nextMultipliers(const assembly::ElementFields &fields) const;

  // Adaptive kappa_AL (augmented Lagrangian): the Uzawa update contracts the multiplier error by
  // about S / (S + kappa_AL) per solve, S the stiffness against an element's volume change at
  // fixed multipliers. An active fibre adds its stress to S through its isochoric stretch (669 kPa
  // against the matrix's mu = 2 kPa at full activation), and with the default 30 mu the loop
  // contracts by about 3/4 per solve and stalls. So in a tissue with active fibres (some family's
  // group at alpha > 0), once a step has taken kSlowSolves solves and the tissue's largest
  // dilatation error fell by less than kSlowContraction over the last tight one, its kappa_AL is
  // raised by kAugmentationGrowth (up to kMaximumPenaltyRatio mu) for the rest of the run, and
  // its tangent's kappa_t with it (Augmentation::setRatio). Loops of a few solves
  // (every stored scene) and tissues without active fibres (the thick sphere near its limit
  // point, where Uzawa slows for another reason) are never touched. Off under a controller (set
  // false by its owner): a raise inside one candidate's solve would change the others', and GA
  // control groups solving different candidates would no longer agree. There the multiplier
  // update is accelerated instead (Incompressibility/multiplier acceleration = auto).
  static constexpr double kSlowContraction = 0.5, kAugmentationGrowth = 10.0, kMaximumPenaltyRatio = 1e5;
  static constexpr int kSlowSolves = 6;
  void allowKappaRaises(bool allow) { allowRaises_ = allow; }
  // kappa_AL / mu of each tissue now.
  const std::vector<double> &penaltyRatios() const { return augmentation_.ratios(); }
  // A restart's: the ratios a checkpoint kept; a tissue whose kappa_AL had been raised gets it
  // again, with its kappa_t. Throws std::invalid_argument for a wrong count.
  void restorePenaltyRatios(const std::vector<double> &ratios);

private:
  const assembly::ResultEvaluator results_;
  const NewtonSolver &newton_;
  bool augmented_;
  bool mixed_;                // element pressures are Newton unknowns (MixedPressureState)
  bool augmentedContact_ = false; // a contact is enforced by the augmented Lagrangian: its gap bounds the loop
  // Stops on the distance from the physical law, with room for more than one Newton solve
  // (augmented Lagrangian and mixed; a penalty makes one solve and reports |theta - 1|).
  bool measuresPhysicalLaw() const { return augmented_ || mixed_; }
  // Per tissue the largest dilatation error of its local elements, maximum over the ranks. Collective.
  std::vector<double> tissueErrors(const assembly::ElementFields &fields) const;
  // Raises kappa_AL of the tissues whose error fell by less than kSlowContraction; true if any.
  bool raiseSlowTissues(const std::vector<double> &errors, const std::vector<double> &previous) const;
  // Per tissue: whether a local element on any rank has a fibre family whose group is active now. Collective.
  std::vector<int> activeTissues() const;
  Augmentation &augmentation_; // per tissue: kappa_AL, its rule, the tangent's law (raised here)
  bool allowRaises_ = true;
  std::vector<int> localTissue_;               // per local element: its tissue
  const AugmentedLagrangianRule &ruleOf(std::size_t localElement) const {
    return augmentation_.rule(static_cast<std::size_t>(localTissue_[localElement]));
  }
  double tolerance_;
  int maxIterations_;
  bool inexact_;              // Uzawa acceleration = inexact inner solves
  double innerTolerance_;     // their relative residual tolerance
  double innerLinearTolerance_; // their Krylov solves' largest relative tolerance
  MultiplierAcceleration acceleration_; // Anderson's update: always, never, or where raises are off
  int andersonDepth_;
  // A fresh Anderson history for one loop, its sums over the ranks of the assembly (none: plain
  // updates).
  std::optional<AndersonAcceleration> multiplierAcceleration() const;
  bool accelerates() const {
    return augmented_ && !mixed_ &&
           (acceleration_ == MultiplierAcceleration::anderson ||
            (acceleration_ == MultiplierAcceleration::automatic && !allowRaises_));
  }
};

} // namespace glossa::solvers
