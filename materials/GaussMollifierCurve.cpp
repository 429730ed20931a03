#include "materials/GaussMollifierCurve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace glossa::materials {

namespace {
// x^n for a small non-negative integer n, by repeated squaring: std::pow dominated the cost of
// the local contractile solve.
double integerPower(double x, int n) {
  double result = 1.0;
  while (n) {
    if (n & 1) result *= x;
    x *= x;
    n >>= 1;
  }
  return result;
}

int smallInteger(double e) { return e >= 0.0 && e <= 64.0 && e == std::floor(e) ? static_cast<int>(e) : -1; }

// x^(e-1) and x^e (x >= 0): the pair each term's value and slope need. At x = 0 the slope factor
// x^(e-1) is taken as 0 below e = 1 (it only ever multiplies sign(d) = 0 there), not as inf.
struct PowerPair {
  double belowOne, full;
};
PowerPair powers(double x, double e, int eInt) {
  if (eInt >= 1) {
    const double below = integerPower(x, eInt - 1);
    return {below, below * x};
  }
  if (x == 0.0 && e < 1.0) return {0.0, e == 0.0 ? 1.0 : 0.0};
  return {std::pow(x, e - 1.0), std::pow(x, e)};
}
}  // namespace

GaussMollifierCurve::GaussMollifierCurve(std::vector<GaussMollifierTerm> terms, double lower, double upper,
                                         double below, double above)
    : terms_(std::move(terms)), lower_(lower), upper_(upper), below_(below), above_(above) {
  if (!(lower < upper) || !(below >= 0.0) || !(above >= 0.0))
    throw std::invalid_argument("GaussMollifierCurve: need lower < upper and non-negative end values");
  // Each term is at most max(A, 0) times the peak of its closing factor, R^(q s).
  double bound = 0.0;
  for (const GaussMollifierTerm &t : terms_) {
    if (!(t.p >= 1.0 && t.B >= 0.0 && std::isfinite(t.A) && std::isfinite(t.mu) && t.R >= 0.0))
      throw std::invalid_argument("GaussMollifierCurve: a term needs p >= 1, B >= 0, R >= 0, finite A, mu");
    if (t.R > 0.0 && !(t.q >= 1.0 && t.s >= 1.0))
      throw std::invalid_argument("GaussMollifierCurve: a closed term needs q >= 1 and s >= 1");
    const double closing = t.R > 0.0 ? std::pow(t.R, t.q * t.s) : 1.0;
    bound += std::max(t.A, 0.0) * closing;
  }
  upperBound_ = std::max({bound, below_, above_});
  for (const GaussMollifierTerm &t : terms_) {
    const int pInt = smallInteger(t.p), qInt = smallInteger(t.q), sInt = smallInteger(t.s);
    const bool quadratic = pInt == 2 && (t.R == 0.0 || (qInt == 2 && sInt >= 1));
    prepared_.push_back({t.R > 0.0 ? std::pow(t.R, t.q) : 0.0, pInt, qInt, sInt, quadratic});
  }
}

double GaussMollifierCurve::zeroBelow() const {
  return below_ == 0.0 ? lower_ : -std::numeric_limits<double>::infinity();
}

CurveValue GaussMollifierCurve::evaluate(double x) const {
  if (x < lower_) return {below_, 0.0};
  if (x > upper_) return {above_, 0.0};
  CurveValue f;
  for (std::size_t k = 0; k < terms_.size(); ++k) {
    const GaussMollifierTerm &t = terms_[k];
    const PreparedTerm &pt = prepared_[k];
    const double d = x - t.mu;
    const double ad = std::abs(d);
    if (t.R > 0.0 && ad >= t.R) continue;  // outside the closing factor's support: no exp needed
    if (pt.quadratic) {
      // The general branch below with p = q = 2, to the bit: |d| |d| = d d, and a product with
      // |d| then sign(d) is the product with d.
      const double d2 = d * d;
      const double G = t.A * std::exp(-t.B * d2);
      const double dG = -G * t.B * t.p * d;
      if (t.R > 0.0) {
        const double w = pt.Rq - d2;
        const double mBelow = integerPower(w, pt.sInt - 1);
        const double dM = -t.s * t.q * mBelow * d;
        f.value += G * (mBelow * w);
        f.slope += dG * (mBelow * w) + G * dM;
      } else {
        f.value += G;
        f.slope += dG;
      }
      continue;
    }
    const double sign = d > 0.0 ? 1.0 : (d < 0.0 ? -1.0 : 0.0);
    // Gauss part G = A exp(-B |d|^p), dG/dx = -G B p |d|^(p-1) sign(d).
    const PowerPair dp = powers(ad, t.p, pt.pInt);
    const double G = t.A * std::exp(-t.B * dp.full);
    const double dG = -G * t.B * t.p * dp.belowOne * sign;
    if (t.R > 0.0) {
      // closing factor M = (R^q - |d|^q)^s, dM/dx = -s q (R^q - |d|^q)^(s-1) |d|^(q-1) sign(d).
      const PowerPair dq = powers(ad, t.q, pt.qInt);
      const PowerPair m = powers(pt.Rq - dq.full, t.s, pt.sInt);
      const double dM = -t.s * t.q * m.belowOne * dq.belowOne * sign;
      f.value += G * m.full;
      f.slope += dG * m.full + G * dM;
    } else {
      f.value += G;
      f.slope += dG;
    }
  }
  return f;
}

}  // namespace glossa::materials
