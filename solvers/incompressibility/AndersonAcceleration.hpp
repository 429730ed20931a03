#pragma once
// Anderson acceleration of the Uzawa loop's multiplier update (doc/incompressibility.md,
// "Accelerating the multiplier update"). The plain update is a fixed-point iteration,
//   Lambda_(k+1) = G(Lambda_k) = beta p(u(Lambda_k))   (AugmentedLagrangianRule),
// which contracts the multiplier error by about S / (S + kappa_AL) per solve, S the stiffness
// against an element's volume change at fixed multipliers. Where fibres are active S is large
// and, under a controller (which may not raise kappa_AL: UzawaLoop), a candidate's loop takes six
// or seven solves at a contraction of 0.3 to 0.75. Anderson's method (Walker and Ni 2011, "type
// II", mixing 1) combines the last m + 1 iterates instead of taking the last one:
//   f_k = G(Lambda_k) - Lambda_k,  gamma = argmin |f_k - dF gamma|,  Lambda_(k+1) = G(Lambda_k) - dG gamma,
// dF and dG the columns f_(j+1) - f_j and G_(j+1) - G_j of the last m pairs. On an affine map it is
// a multisecant (GMRES-like) method: a few slow modes are removed in as many updates, where a
// single relaxation factor (Aitken's) would overshoot the fast ones.
//
// Per local element, Eigen only; the inner products are summed over the ranks by `sumAll`
// (in one fixed order, so a run and its restart agree). The history lives for one Uzawa loop:
// every candidate of a controller starts afresh, so control groups still agree bit for bit.

#include <deque>
#include <functional>
#include <vector>

namespace glossa::solvers {

class AndersonAcceleration {
public:
  // Sums `count` doubles over every rank in place (collective); a single rank: nothing to do.
  using SumAll = std::function<void(double *values, int count)>;
  // `depth` m >= 1: the most pairs kept.
  explicit AndersonAcceleration(int depth, SumAll sumAll = {});

  // The next multipliers from the current ones and their plain update G(lambda). The first call
  // after reset() returns `plain` itself.
  std::vector<double> next(const std::vector<double> &lambda, const std::vector<double> &plain);
  // Forgets the history: the map changed (another load, contact multipliers moved) or the last
  // accelerated update did not reduce the error.
  void reset();
  // Pairs in the history now (at most depth).
  int pairs() const { return static_cast<int>(differencesF_.size()); }

private:
  int depth_;
  SumAll sumAll_;
  std::vector<double> lastF_, lastG_; // f and G of the last call (empty after reset)
  std::deque<std::vector<double>> differencesF_, differencesG_;
};

} // namespace glossa::solvers
