#include "materials/GaussMollifierCurve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace glossa::materials {

namespace {
// x^e, by repeated squaring when e is a small non-negative integer (all of Table II's and the
// fitted exponents): std::pow dominated the cost of the local contractile solve.
double power(double x, double e) {
  if (e >= 0.0 && e <= 64.0 && e == std::floor(e)) {
    auto n = static_cast<unsigned>(e);
    double result = 1.0;
    while (n) {
      if (n & 1u) result *= x;
      x *= x;
      n >>= 1u;
    }
    return result;
  }
  return std::pow(x, e);
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
}

double GaussMollifierCurve::zeroBelow() const {
  return below_ == 0.0 ? lower_ : -std::numeric_limits<double>::infinity();
}

CurveValue GaussMollifierCurve::evaluate(double x) const {
  if (x < lower_) return {below_, 0.0};
  if (x > upper_) return {above_, 0.0};
  CurveValue f;
  for (const GaussMollifierTerm &t : terms_) {
    const double d = x - t.mu;
    const double ad = std::abs(d);
    const double sign = d > 0.0 ? 1.0 : (d < 0.0 ? -1.0 : 0.0);
    // Gauss part G = A exp(-B |d|^p), dG/dx = -G B p |d|^(p-1) sign(d).
    const double G = t.A * std::exp(-t.B * power(ad, t.p));
    const double dG = ad > 0.0 ? -G * t.B * t.p * power(ad, t.p - 1.0) * sign : 0.0;
    if (t.R > 0.0) {
      if (ad >= t.R) continue;
      // closing factor M = (R^q - |d|^q)^s, dM/dx = -s q (R^q - |d|^q)^(s-1) |d|^(q-1) sign(d).
      const double base = power(t.R, t.q) - power(ad, t.q);
      const double M = power(base, t.s);
      const double dM =
          ad > 0.0 ? -t.s * t.q * power(base, t.s - 1.0) * power(ad, t.q - 1.0) * sign : 0.0;
      f.value += G * M;
      f.slope += dG * M + G * dM;
    } else {
      f.value += G;
      f.slope += dG;
    }
  }
  return f;
}

}  // namespace glossa::materials
