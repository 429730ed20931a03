#pragma once
// Limit points of a load path (doc/theory.md, "Limit points"). Under load control a path with a
// maximum (the thick sphere's pressure, a snap-through) has no equilibrium nearby past it, and
// before it Newton can converge to the other, unstable branch within one step without a word.
// After each converged step the tangent's stiffness along the path is measured
// (solvers/stepping/PathStiffness),
//   s_k = u'^T K(u_k) u' / u'^T u',   u' = du/dt = -K^-1 df/dt,
// and the monitor reports it relative to the first step's: the current stiffness parameter
// S_k = s_k / s_1 (Bergan's, with the path tangent in place of the secant). S is 1 on a linear
// path, falls to 0 at a limit point and is negative past one: the converged state is an
// unstable equilibrium. Such a step is refused, and while the step is cut back the monitor
// brackets the limit point between the last accepted time and the earliest refused one; once
// the step needed falls below the bracket tolerance the run stops, naming it.
// This part is pure: the measurement is PathStiffness's (Trilinos).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace glossa::solvers {

class LimitPointMonitor {
public:
  // A step is cut back inside a bracket until it is below `tolerance` times the nominal step.
  LimitPointMonitor(double nominalStep, double tolerance) : nominal_(nominalStep), tolerance_(tolerance) {}

  // S of a converged trial state from its stiffness s along the path (the first finite positive s
  // becomes the reference; NaN before one).
  double relativeStiffness(double s);
  // Past a limit point: S <= 0.
  static bool beyond(double S) { return S <= 0.0; }
  // An accepted step at time t with relative stiffness S.
  void accepted(double t, double S);
  // A refused trial to `trialTime` from the committed time `t`: `unstable` if it converged with
  // S <= 0. Opens (or narrows) the bracket when it is unstable, or when the path had already
  // softened below `kSoftened` (Newton then finds no equilibrium past the maximum at all).
  void refused(double t, double trialTime, bool unstable, std::size_t largestMotionNode);
  // The limit point is located once a bracket is open and the next step would be below the tolerance.
  bool located(double nextStep) const { return bracket_.has_value() && nextStep < tolerance_ * nominal_; }
  // The stop's reason, in words, and its record for summary.json.
  std::string description(const Eigen::Vector3d &nodePosition) const;
  nlohmann::json record(const Eigen::Vector3d &nodePosition) const;
  std::size_t node() const { return bracket_ ? bracket_->node : 0; }

  // An accepted step with S below this has the path near its maximum: a failure there is a limit point.
  static constexpr double kSoftened = 0.1;

  // What a checkpoint keeps (s_1, the last S, an open bracket) and its restoration.
  nlohmann::json state() const;
  void restore(const nlohmann::json &state);

private:
  struct Bracket {
    double lower, upper; // the last accepted time, the earliest refused one
    bool unstable;       // a state past it converged (S <= 0), not only Newton failing
    std::size_t node;    // where it moves most (along the unstable step, or in all)
  };
  double nominal_, tolerance_;
  double reference_ = 0.0; // s_1
  double lastS_ = 1.0; // S of the last accepted step
  std::optional<Bracket> bracket_;
};

} // namespace glossa::solvers
