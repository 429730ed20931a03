#include "control/BoundedLeastSquares.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace glossa::control {

namespace {
enum class State { free, atLower, atUpper };
}  // namespace

BoundedLeastSquaresResult solveBoundedLeastSquares(const Eigen::MatrixXd &A, const Eigen::VectorXd &b,
                                                   const Eigen::VectorXd &lower, const Eigen::VectorXd &upper,
                                                   double rho) {
  const Eigen::Index n = A.cols();
  if (A.rows() != b.size() || lower.size() != n || upper.size() != n)
    throw std::invalid_argument("bounded least squares: A is " + std::to_string(A.rows()) + " x " +
                                std::to_string(n) + ", b has " + std::to_string(b.size()) + " entries, the bounds " +
                                std::to_string(lower.size()) + " and " + std::to_string(upper.size()));
  if (!(rho >= 0.0) || !std::isfinite(rho)) throw std::invalid_argument("bounded least squares: rho must be >= 0");
  for (Eigen::Index i = 0; i < n; ++i)
    if (!std::isfinite(lower(i)) || !std::isfinite(upper(i)) || lower(i) > upper(i))
      throw std::invalid_argument("bounded least squares: bounds of variable " + std::to_string(i) +
                                  " must be finite with lower <= upper");

  // Normal equations: the problems are tiny (n muscle groups) and rho regularises them.
  const Eigen::MatrixXd H = A.transpose() * A + rho * Eigen::MatrixXd::Identity(n, n);
  const Eigen::VectorXd g0 = A.transpose() * b;
  const double scale = std::max(1.0, H.diagonal().cwiseAbs().maxCoeff());
  const double tol = 1e-12 * scale * (1.0 + upper.cwiseAbs().maxCoeff() + lower.cwiseAbs().maxCoeff());

  // Start from the origin projected onto the box, every variable at a bound if the origin is
  // outside it, free otherwise.
  BoundedLeastSquaresResult r;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n).cwiseMax(lower).cwiseMin(upper);
  std::vector<State> state(static_cast<std::size_t>(n), State::free);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (lower(i) == upper(i) || (x(i) == lower(i) && lower(i) > 0.0)) state[i] = State::atLower;
    else if (x(i) == upper(i) && upper(i) < 0.0) state[i] = State::atUpper;
  }
  const int maxIterations = 10 * static_cast<int>(n) + 20;
  for (r.iterations = 0; r.iterations < maxIterations; ++r.iterations) {
    // Solve for the free variables with the others at their bounds.
    std::vector<Eigen::Index> F;
    for (Eigen::Index i = 0; i < n; ++i)
      if (state[i] == State::free) F.push_back(i);
    Eigen::VectorXd z = x;
    if (!F.empty()) {
      const auto m = static_cast<Eigen::Index>(F.size());
      Eigen::MatrixXd HF(m, m);
      Eigen::VectorXd rhs(m);
      for (Eigen::Index a = 0; a < m; ++a) {
        rhs(a) = g0(F[a]);
        for (Eigen::Index j = 0; j < n; ++j)
          if (state[j] != State::free) rhs(a) -= H(F[a], j) * x(j);
        for (Eigen::Index c = 0; c < m; ++c) HF(a, c) = H(F[a], F[c]);
      }
      const Eigen::VectorXd zF = HF.ldlt().solve(rhs);
      for (Eigen::Index a = 0; a < m; ++a) z(F[a]) = zF(a);
    }
    // Step from x towards z as far as the box allows; a variable that reaches a bound is fixed.
    double t = 1.0;
    Eigen::Index blocking = -1;
    for (Eigen::Index i : F) {
      const double d = z(i) - x(i);
      if (z(i) < lower(i) - tol && d < 0.0 && (lower(i) - x(i)) / d < t) t = (lower(i) - x(i)) / d, blocking = i;
      if (z(i) > upper(i) + tol && d > 0.0 && (upper(i) - x(i)) / d < t) t = (upper(i) - x(i)) / d, blocking = i;
    }
    t = std::clamp(t, 0.0, 1.0);
    for (Eigen::Index i : F) x(i) = std::clamp(x(i) + t * (z(i) - x(i)), lower(i), upper(i));
    if (blocking >= 0) {
      state[blocking] = z(blocking) < lower(blocking) ? State::atLower : State::atUpper;
      x(blocking) = state[blocking] == State::atLower ? lower(blocking) : upper(blocking);
      continue;
    }
    // The free variables are optimal; free the bound variable whose gradient points into the box
    // most strongly (KKT multiplier of the wrong sign), or stop.
    const Eigen::VectorXd gradient = H * x - g0;
    Eigen::Index release = -1;
    double worst = tol;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (lower(i) == upper(i)) continue;
      const double pull = state[i] == State::atLower ? -gradient(i) : state[i] == State::atUpper ? gradient(i) : 0.0;
      if (pull > worst) worst = pull, release = i;
    }
    if (release < 0) {
      r.converged = true;
      break;
    }
    state[release] = State::free;
  }
  r.x = x;
  return r;
}

}  // namespace glossa::control
