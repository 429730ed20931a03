#pragma once
// Where the gradient controller's candidate solves start (doc/control.md, "Where a candidate
// starts"). A candidate of the Gauss-Newton line search lies near the accepted state x_a, whose
// sensitivities dx/du the controller has just computed. Its solution is, to first order,
//   x(u) = x_a + (dx/du) (u - u_a),   p_e(u) = p_e,a + (dp_e/du) (u - u_a),
// with dx/du and dp_e/du the linearised response of the converged augmented-Lagrangian problem
// (the tangent with the physical bulk modulus, ConstrainedTangent). So the candidate's Newton
// solves start at the moved state, and its Uzawa loop at the multipliers its rule gives the
// predicted element pressures (AugmentedLagrangianRule: Lambda = beta p). From the step's start
// instead, a candidate takes 4 to 5 Newton solves (the multipliers' error contracts by 0.3 per
// update under a controller); from here, mostly 2.
//
// The GA's candidates start likewise from the state of its Gauss-Newton seed's solve (the
// previous step's best inputs), which every control group solves and linearises alike, so the
// groups still agree bit for bit: one CandidateStart for the step, never moved to a group's own
// best.

#include <vector>

#include "assembly/ResultEvaluator.hpp"
#include "solvers/incompressibility/UzawaLoop.hpp"
#include "solvers/run/StepState.hpp"

namespace glossa::solvers {

class CandidateStart {
public:
  // Nothing to predict from (another step, or another state kept).
  void forget();
  bool ready() const { return !responses_.is_null(); }

  // The accepted state's response: its inputs (one per muscle group of the scene), du/du_M for
  // `groups` (columns of `responses`), its element pressures and dp_e/du_M per group (both empty:
  // the multipliers are kept as they are, e.g. under a penalty).
  void record(const std::vector<double> &inputs, const std::vector<int> &groups,
              const Teuchos::RCP<const assembly::MultiVector> &responses, std::vector<double> pressure,
              std::vector<std::vector<double>> pressureResponses);

  // `start` (the accepted state on entry) moved to the candidate with `inputs`: its displacement
  // along the responses, its multipliers from the predicted pressures by `uzawa`'s rule.
  void predict(const std::vector<double> &inputs, const UzawaLoop &uzawa, StepState &start) const;

private:
  std::vector<double> inputs_;
  std::vector<int> groups_;
  Teuchos::RCP<const assembly::MultiVector> responses_;
  std::vector<double> pressure_;
  std::vector<std::vector<double>> pressureResponses_;
};

// dp_e/du_M of every local element along each response column, with the tangent's volumetric laws
// (the caller's ConstrainedTangent alive, `lambda` its multipliers): central differences of the
// element pressures at u +- epsilon r_M. theta_e is a cubic in u, so the difference is its
// derivative to order epsilon^2. Collective.
std::vector<std::vector<double>> elementPressureResponses(const assembly::ResultEvaluator &results,
                                                          const assembly::Vector &u, const std::vector<double> &lambda,
                                                          const assembly::MultiVector &responses);

} // namespace glossa::solvers
