#pragma once
// A safeguarded (hybrid bisection-Newton) scalar root finder, the local solve of the Hill
// contractile stretch (paper §5.2, "a hybrid bisection-Newton method [46]"): Newton steps while
// they stay inside the current sign-change bracket and reduce |f| fast enough, bisection
// otherwise, so it always converges on a valid bracket. Every outcome carries a status that
// says why it stopped.

#include <algorithm>
#include <cmath>

namespace glossa::materials {

enum class ScalarSolveStatus {
  Converged,          // |step| <= xTolerance and |f| <= max(residualTolerance, 8 xTolerance |x f'|)
  InvalidBracket,     // f(lo) and f(hi) have the same sign, or lo >= hi
  NonFinite,          // f or f' returned NaN/inf, or the input was not finite
  MaxIterations,      // maxIterations reached before the step fell below xTolerance
  ResidualNotReduced  // the bracket collapsed to xTolerance but |f| > residualTolerance: f jumps
};

struct ScalarSolveOptions {
  double xTolerance = 1e-14;        // on |step| relative to max(|x|, 1)
  double residualTolerance = 1e-9;  // absolute, in f's units
  int maxIterations = 200;
};

struct ScalarSolveResult {
  double x = 0.0;
  // f and f' at the last point evaluated: x itself, or, when a Newton step below xTolerance
  // ended the solve, the point that step started from (at most xTolerance max(|x|, 1) away).
  double f = 0.0;
  double slope = 0.0;
  int iterations = 0;
  ScalarSolveStatus status = ScalarSolveStatus::NonFinite;
};

struct ValueSlope {
  double value;
  double slope;
};

class BracketedNewtonSolver {
 public:
  explicit BracketedNewtonSolver(ScalarSolveOptions options = {}) : options_(options) {}

  // Finds a root of fn (returning ValueSlope) in [lo, hi], starting from x0 (clamped into the
  // bracket; the midpoint if x0 is not finite).
  template <class Fn>
  ScalarSolveResult solve(Fn &&fn, double lo, double hi, double x0) const;

  const ScalarSolveOptions &options() const { return options_; }

 private:
  ScalarSolveOptions options_;
};

inline const char *describe(ScalarSolveStatus status) {
  switch (status) {
    case ScalarSolveStatus::Converged:
      return "converged";
    case ScalarSolveStatus::InvalidBracket:
      return "no sign change on the bracket";
    case ScalarSolveStatus::NonFinite:
      return "non-finite value or slope";
    case ScalarSolveStatus::MaxIterations:
      return "maximum iterations reached";
    case ScalarSolveStatus::ResidualNotReduced:
      return "bracket collapsed on a jump of the residual";
  }
  return "?";
}

template <class Fn>
ScalarSolveResult BracketedNewtonSolver::solve(Fn &&fn, double lo, double hi, double x0) const {
  ScalarSolveResult r;
  auto finite = [](const ValueSlope &v) { return std::isfinite(v.value) && std::isfinite(v.slope); };
  auto done = [&](double x, const ValueSlope &v, ScalarSolveStatus s) {
    r.x = x;
    r.f = v.value;
    r.slope = v.slope;
    r.status = s;
    return r;
  };
  if (!std::isfinite(lo) || !std::isfinite(hi)) return done(lo, {NAN, NAN}, ScalarSolveStatus::NonFinite);
  if (!(lo < hi)) return done(lo, {NAN, NAN}, ScalarSolveStatus::InvalidBracket);
  // The sign-change bracket xNeg, xPos (f(xNeg) < 0 < f(xPos)) starts as [lo, hi] with the end
  // values unknown: a warm-started Newton iteration that stays inside [lo, hi] never needs them,
  // and the local contractile solve, started from the last root, mostly is one (two end
  // evaluations of eight per solve). They are evaluated, and the bracket checked, at the first
  // bisection.
  bool bracketKnown = false;
  double xNeg = NAN, xPos = NAN;  // the iterates so far with f < 0 and f > 0
  double x = std::isfinite(x0) ? std::clamp(x0, lo, hi) : 0.5 * (lo + hi);
  double stepBeforeLast = hi - lo, step = stepBeforeLast;
  ValueSlope fx = fn(x);
  for (r.iterations = 1; r.iterations <= options_.maxIterations; ++r.iterations) {
    if (!finite(fx)) return done(x, fx, ScalarSolveStatus::NonFinite);
    if (fx.value == 0.0) return done(x, fx, ScalarSolveStatus::Converged);
    if (fx.value < 0.0)
      xNeg = x;
    else
      xPos = x;
    const double newton = fx.slope != 0.0 ? x - fx.value / fx.slope : NAN;
    const double a = bracketKnown ? std::min(xNeg, xPos) : lo, b = bracketKnown ? std::max(xNeg, xPos) : hi;
    // Bisect when Newton leaves the bracket or |f| does not fall fast enough (|2 f| > |step f'|).
    if (!(newton >= a && newton <= b) || std::abs(2.0 * fx.value) > std::abs(stepBeforeLast * fx.slope)) {
      if (!bracketKnown) {
        const ValueSlope flo = fn(lo), fhi = fn(hi);
        if (!finite(flo)) return done(lo, flo, ScalarSolveStatus::NonFinite);
        if (!finite(fhi)) return done(hi, fhi, ScalarSolveStatus::NonFinite);
        if (flo.value == 0.0) return done(lo, flo, ScalarSolveStatus::Converged);
        if (fhi.value == 0.0) return done(hi, fhi, ScalarSolveStatus::Converged);
        if ((flo.value > 0.0) == (fhi.value > 0.0)) return done(lo, flo, ScalarSolveStatus::InvalidBracket);
        // Any point of f < 0 and any of f > 0 bracket a root: the closest pair of the end
        // points and the iterates evaluated so far.
        const double negs[2] = {flo.value < 0.0 ? lo : hi, xNeg}, poss[2] = {flo.value < 0.0 ? hi : lo, xPos};
        double width = INFINITY;
        for (double n : negs)
          for (double p : poss)
            if (std::isfinite(n) && std::isfinite(p) && std::abs(n - p) < width) {
              width = std::abs(n - p);
              xNeg = n;
              xPos = p;
            }
        bracketKnown = true;
      }
      const double aa = std::min(xNeg, xPos), bb = std::max(xNeg, xPos);
      stepBeforeLast = step;
      step = 0.5 * (bb - aa);
      x = aa + step;
    } else {
      stepBeforeLast = step;
      step = x - newton;
      // Converged once |f| is below the absolute tolerance and the Newton step below the
      // x-resolution: x - f/f' is then the root to round-off (quadratic convergence), and
      // neither it nor a polish needs another evaluation; f and f' are reported at x, at most
      // xTolerance away. (A small step alone is not enough: at a kink of f, e.g. where the
      // series element goes slack, a one-sided slope can make it small far from the root.)
      if (std::abs(fx.value) <= options_.residualTolerance &&
          std::abs(step) <= options_.xTolerance * std::max(std::abs(newton), 1.0))
        return done(newton, fx, ScalarSolveStatus::Converged);
      x = newton;
    }
    fx = fn(x);
    if (std::abs(step) <= options_.xTolerance * std::max(std::abs(x), 1.0)) {
      if (!finite(fx)) return done(x, fx, ScalarSolveStatus::NonFinite);
      // Polish: one more Newton step if it stays in the bracket and reduces |f| (after a final
      // bisection step the iterate is only as good as the bracket width).
      if (fx.value != 0.0 && fx.slope != 0.0) {
        const double polished = x - fx.value / fx.slope;
        if (polished >= std::min(xNeg, xPos) && polished <= std::max(xNeg, xPos)) {
          const ValueSlope fp = fn(polished);
          if (finite(fp) && std::abs(fp.value) < std::abs(fx.value)) {
            x = polished;
            fx = fp;
          }
        }
      }
      // The residual must be small in absolute terms or at the level the x-resolution allows.
      const double resolved = 8.0 * options_.xTolerance * std::max(std::abs(x), 1.0) * std::abs(fx.slope);
      return done(x, fx,
                  std::abs(fx.value) <= std::max(options_.residualTolerance, resolved)
                      ? ScalarSolveStatus::Converged
                      : ScalarSolveStatus::ResidualNotReduced);
    }
  }
  r.iterations = options_.maxIterations;
  return done(x, fx, ScalarSolveStatus::MaxIterations);
}

}  // namespace glossa::materials
