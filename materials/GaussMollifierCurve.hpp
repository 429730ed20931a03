#pragma once
// The Gauss-mollifier curves of the Hill contractile element (paper eq. 19-21), with the closing
// factor as doc/materials.md resolves eq. 21:
//   g_n(x) = A_n exp(-B_n |x - mu_n|^p_n) (R_n^q_n - |x - mu_n|^q_n)^s_n   for |x - mu_n| < R_n,
//   g_n(x) = 0 for |x - mu_n| >= R_n, and the closing factor is 1 where R_n = 0.
// f(x) = sum_n g_n(x) on [lower, upper] (both included), `below` for x < lower and `above` for
// x > upper: eq. 19 (f_cL: 0 outside [0.5, 2]) and eq. 20 (f_cV: 0 below -10, 1.5 above 10).

#include <string>
#include <vector>

#include "materials/ForceCurve.hpp"

namespace glossa::materials {

struct GaussMollifierTerm {
  double mu = 0.0;  // centre
  double p = 2.0;   // Gauss exponent
  double A = 0.0;   // amplitude
  double B = 0.0;   // Gauss rate
  double R = 0.0;   // closing radius; 0: no closing factor
  double q = 0.0;   // closing-factor exponents
  double s = 0.0;
};

class GaussMollifierCurve final : public ForceCurve {
 public:
  // Throws std::invalid_argument unless lower < upper, below >= 0, above >= 0, and each term
  // has p >= 1, B >= 0, A finite, R >= 0 and (R = 0 or q >= 1 and s >= 1).
  GaussMollifierCurve(std::vector<GaussMollifierTerm> terms, double lower, double upper, double below,
                      double above);

  CurveValue evaluate(double x) const override;
  double upperBound() const override { return upperBound_; }
  double zeroBelow() const override;  // lower if below = 0, else -infinity

  const std::vector<GaussMollifierTerm> &terms() const { return terms_; }
  double lower() const { return lower_; }
  double upper() const { return upper_; }

 private:
  // What evaluate() derives from each term once: R^q, and the exponents as integers where they
  // are (every exponent of both parameter sets), so that |d|^p and |d|^(p-1) come from one
  // product chain. prepared_[k] belongs to terms_[k].
  struct PreparedTerm {
    double Rq;
    int pInt, qInt, sInt;  // -1: not a small non-negative integer, std::pow
    // p = 2 and, closed, q = 2 and s a positive integer (every term of both parameter sets but
    // the paper's p = 1, 4 and 8 ones): |d|^p = d^2 and sign(d) |d| = d, no power chains.
    bool quadratic;
  };
  std::vector<GaussMollifierTerm> terms_;
  std::vector<PreparedTerm> prepared_;
  double lower_, upper_, below_, above_;
  double upperBound_;
};

}  // namespace glossa::materials
