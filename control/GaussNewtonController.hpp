#pragma once
// The gradient-based controller of a control step (beyond the paper's GA; doc/control.md): a projected,
// damped Gauss-Newton iteration on the continuous neural inputs u in [0, 1]^n of the evaluated
// muscle groups. With r(u) the weighted offsets of the control points from their goals
// (r_p = w_p (x_p - xbar_p), stacked, 3 per point) and S = dr/du from the converged tangent
// (one linear solve per muscle, solvers/control/ControlSensitivity.hpp), each iteration solves
//
//   min_du |S du + r|^2 + rho |du|^2   subject to  0 <= u + du <= 1
//
// exactly (BoundedLeastSquares.hpp), then evaluates u + t du by a full solve, halving t until the
// sum of squares falls (at most `maxBacktracks` times). It minimises sum_p |r_p|^2, whose
// minimiser is that of eq. 25 (sum_p |r_p|) when one point dominates or all can be held; the
// objective it reports is eq. 25, like the GA's. Standard C++17 and Eigen only: the full solves
// and the sensitivities come through callbacks.

#include <functional>
#include <string>

#include <Eigen/Core>

namespace glossa::control {

struct GaussNewtonParameters {
  int maxIterations = 4;           // Gauss-Newton iterations (sensitivity evaluations) per step, [1, inf)
  int maxBacktracks = 3;           // step halvings per iteration, [0, inf)
  double stepTolerance = 1e-3;     // stop when max_M |du_M| falls below this, (0, 1]
  double damping = 1e-6;           // rho relative to the largest diagonal entry of S^T S, [0, inf)
  double objectiveTolerance = 0.0; // stop once eq. 25 is <= this [m], [0, inf)

  // Throws std::invalid_argument naming the bad field (prefixed by `prefix`) and its range.
  void validate(const std::string &prefix = "") const;
};

// One full solve of the step at the inputs `u`: `ok` false if it failed (then the rest is unused).
struct ControlEvaluation {
  bool ok = false;
  Eigen::VectorXd residual;  // r: 3 per control point, weighted
  double objective = 0.0;    // eq. 25: sum_p |r_p|
};

enum class GaussNewtonStop {
  objectiveTolerance,  // eq. 25 reached the tolerance
  stationary,          // the bounded step fell below stepTolerance
  noDescent,           // no step length lowered the sum of squares
  iterationLimit,      // maxIterations sensitivity evaluations were used
  startFailed,         // the solve at the starting inputs failed
  sensitivityFailed    // the sensitivity at the accepted inputs could not be computed
};
std::string toString(GaussNewtonStop stop);

struct GaussNewtonResult {
  Eigen::VectorXd inputs;   // the best inputs evaluated (those of `objective`)
  double objective = 0.0;   // eq. 25 at `inputs`
  int evaluations = 0;      // full solves
  int sensitivities = 0;    // sensitivity evaluations (each one linear solve per muscle)
  int iterations = 0;       // accepted Gauss-Newton steps
  GaussNewtonStop stop = GaussNewtonStop::iterationLimit;
};

class GaussNewtonController {
public:
  // The full solve at u. The controller only ever asks for the sensitivity at the last
  // evaluation it accepted, so a caller that keeps the state of each evaluation that lowered the
  // sum of squares (below every earlier one) can compute S there.
  using Evaluator = std::function<ControlEvaluation(const Eigen::VectorXd &u)>;
  // S = dr/du (rows as ControlEvaluation::residual, one column per input) at the accepted state;
  // an empty matrix when it could not be computed (the search then stops at the accepted inputs).
  using Sensitivity = std::function<Eigen::MatrixXd(const Eigen::VectorXd &u)>;

  // Throws std::invalid_argument for invalid parameters.
  explicit GaussNewtonController(const GaussNewtonParameters &parameters);

  // From `start` (clipped to [0, 1]). The evaluator's exceptions pass through.
  GaussNewtonResult minimise(const Eigen::VectorXd &start, const Evaluator &evaluate,
                             const Sensitivity &sensitivity) const;

private:
  GaussNewtonParameters p_;
};

}  // namespace glossa::control
