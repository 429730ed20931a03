#include "solvers/incompressibility/AndersonAcceleration.hpp"

#include <stdexcept>
#include <string>

#include <Eigen/Dense>

namespace glossa::solvers {

AndersonAcceleration::AndersonAcceleration(int depth, SumAll sumAll) : depth_(depth), sumAll_(std::move(sumAll)) {
  if (depth < 1) throw std::invalid_argument("AndersonAcceleration: depth " + std::to_string(depth) + " (at least 1)");
}

void AndersonAcceleration::reset() {
  lastF_.clear();
  lastG_.clear();
  differencesF_.clear();
  differencesG_.clear();
}

std::vector<double> AndersonAcceleration::next(const std::vector<double> &lambda, const std::vector<double> &plain) {
  if (lambda.size() != plain.size())
    throw std::invalid_argument("AndersonAcceleration::next: " + std::to_string(lambda.size()) + " multipliers, " +
                                std::to_string(plain.size()) + " updates");
  const std::size_t n = lambda.size();
  std::vector<double> f(n);
  for (std::size_t i = 0; i < n; ++i) f[i] = plain[i] - lambda[i];
  if (!lastF_.empty()) {
    if (lastF_.size() != n) throw std::invalid_argument("AndersonAcceleration::next: the element count changed");
    std::vector<double> dF(n), dG(n);
    for (std::size_t i = 0; i < n; ++i) {
      dF[i] = f[i] - lastF_[i];
      dG[i] = plain[i] - lastG_[i];
    }
    differencesF_.push_back(std::move(dF));
    differencesG_.push_back(std::move(dG));
    if (static_cast<int>(differencesF_.size()) > depth_) {
      differencesF_.pop_front();
      differencesG_.pop_front();
    }
  }
  lastF_ = f;
  lastG_ = plain;
  const int m = pairs();
  if (m == 0) return plain;

  // The normal equations of min |f - dF gamma|: dF^T dF (upper triangle) and dF^T f, summed over
  // the ranks in one call.
  std::vector<double> sums(static_cast<std::size_t>(m * (m + 1) / 2 + m), 0.0);
  std::size_t k = 0;
  for (int a = 0; a < m; ++a)
    for (int b = a; b < m; ++b, ++k)
      for (std::size_t i = 0; i < n; ++i) sums[k] += differencesF_[a][i] * differencesF_[b][i];
  for (int a = 0; a < m; ++a, ++k)
    for (std::size_t i = 0; i < n; ++i) sums[k] += differencesF_[a][i] * f[i];
  if (sumAll_) sumAll_(sums.data(), static_cast<int>(sums.size()));
  Eigen::MatrixXd gram(m, m);
  Eigen::VectorXd rhs(m);
  k = 0;
  for (int a = 0; a < m; ++a)
    for (int b = a; b < m; ++b, ++k) gram(a, b) = gram(b, a) = sums[k];
  for (int a = 0; a < m; ++a, ++k) rhs(a) = sums[k];
  // Nearly parallel differences (a converged mode) make the Gram matrix singular: a relative
  // Tikhonov term keeps gamma bounded without changing a well-posed fit.
  const double scale = gram.trace();
  if (!(scale > 0.0)) return plain;
  gram.diagonal().array() += 1e-12 * scale;
  const Eigen::VectorXd gamma = gram.ldlt().solve(rhs);
  if (!gamma.allFinite()) return plain;
  std::vector<double> out = plain;
  for (int a = 0; a < m; ++a)
    for (std::size_t i = 0; i < n; ++i) out[i] -= gamma(a) * differencesG_[a][i];
  return out;
}

} // namespace glossa::solvers
