#include "fem/TurnedOverVolume.hpp"

#include <algorithm>
#include <array>

#include <Eigen/LU>

namespace glossa::fem {

namespace {
// Sub-boxes are split at most this often: leaves of 1/8 of the element's edge, where the Simpson
// rule on the sign-changing ones errs by less than 1e-5 of the element's volume against a
// threshold of 2.5e-3 (a cube with a corner node at its centre: 0.3084 % of its volume at 3
// levels, 0.3075 % at 5; a sliver at a poor corner 0.0246 % at 3, 0.0241 % at 5).
constexpr int kMaximumDepth = 3;

struct Box {
  Eigen::Vector3d lo, hi;
};

// det dx/dxi at the 27 points (lo, middle, hi)^3 of the box, index 9 i + 3 j + k.
std::array<double, 27> boxDeterminants(const NodeMatrix &x, const Box &box) {
  const Eigen::Vector3d mid = 0.5 * (box.lo + box.hi);
  const std::array<Eigen::Vector3d, 3> at = {box.lo, mid, box.hi};
  std::array<double, 27> f{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d xi(at[i](0), at[j](1), at[k](2));
        f[9 * i + 3 * j + k] = (x.transpose() * hexShapeGradient(xi)).determinant();
      }
  return f;
}

// The Bernstein coefficients of the tri-quadratic through the 27 values: along each axis the
// values (f0, fm, f1) of a quadratic have the coefficients (f0, 2 fm - (f0 + f1) / 2, f1).
std::array<double, 27> bernstein(std::array<double, 27> f) {
  const int stride[3] = {9, 3, 1};
  for (int axis = 0; axis < 3; ++axis)
    for (int n = 0; n < 27; ++n) {
      if ((n / stride[axis]) % 3 != 1) continue;
      f[n] = 2.0 * f[n] - 0.5 * (f[n - stride[axis]] + f[n + stride[axis]]);
    }
  return f;
}

double negativePart(const NodeMatrix &x, const Box &box, int depth) {
  const std::array<double, 27> f = boxDeterminants(x, box);
  const std::array<double, 27> b = bernstein(f);
  const auto [low, high] = std::minmax_element(b.begin(), b.end());
  const Eigen::Vector3d size = box.hi - box.lo;
  const double volume = size.prod(); // in xi
  if (*low >= 0.0) return 0.0;
  // Each quadratic Bernstein polynomial averages 1/3 over its interval: the box's mean of det is
  // the mean of the coefficients.
  double sum = 0.0;
  for (double c : b) sum += c;
  if (*high <= 0.0) return -volume * sum / 27.0;
  if (depth == 0) {
    const double w[3] = {1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0};
    double integral = 0.0;
    for (int n = 0; n < 27; ++n) integral += w[n / 9] * w[(n / 3) % 3] * w[n % 3] * std::max(0.0, -f[n]);
    return volume * integral;
  }
  const Eigen::Vector3d mid = 0.5 * (box.lo + box.hi);
  double total = 0.0;
  for (int c = 0; c < 8; ++c) {
    Box sub = box;
    for (int axis = 0; axis < 3; ++axis) ((c >> axis) & 1 ? sub.lo : sub.hi)(axis) = mid(axis);
    total += negativePart(x, sub, depth - 1);
  }
  return total;
}
} // namespace

double turnedOverVolume(const NodeMatrix &x) {
  return negativePart(x, {Eigen::Vector3d::Constant(-1.0), Eigen::Vector3d::Constant(1.0)}, kMaximumDepth);
}

double hexVolume(const NodeMatrix &X) {
  double volume = 0.0;
  for (const auto &q : gaussHex2()) volume += q.weight * (X.transpose() * hexShapeGradient(q.xi)).determinant();
  return volume;
}

double turnedOverFraction(const NodeMatrix &X, const NodeMatrix &u) {
  const double turned = turnedOverVolume(X + u);
  if (turned == 0.0) return 0.0;
  const double volume = hexVolume(X);
  if (!(volume > 0.0)) return 0.0;
  return std::max(0.0, (turned - turnedOverVolume(X)) / volume);
}

} // namespace glossa::fem
