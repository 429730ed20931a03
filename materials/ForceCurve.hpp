#pragma once
// A scalar scaling curve of the Hill contractile element (paper eq. 16, 19-20): the
// force-length curve f_cL(lambda_c) or the force-velocity curve f_cV(d lambda_c/dt). The one
// small interface behind which the parameter sets live (GaussMollifierCurve with `paper-table-II`
// or `physiological` values; a corrected table or another family drops in here).

namespace glossa::materials {

struct CurveValue {
  double value = 0.0;  // f(x) >= 0
  double slope = 0.0;  // df/dx (one-sided where f has a kink)
};

class ForceCurve {
 public:
  virtual ~ForceCurve() = default;
  virtual CurveValue evaluate(double x) const = 0;
  // An upper bound of f over all x (brackets the local contractile solve).
  virtual double upperBound() const = 0;
  // f(x) = 0 for every x < zeroBelow() (for f_cV: minus the maximum shortening velocity).
  virtual double zeroBelow() const = 0;
};

}  // namespace glossa::materials
