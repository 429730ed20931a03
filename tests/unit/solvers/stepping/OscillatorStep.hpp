#pragma once
// One step of the single oscillator m u'' + c u' + k u = 0 (m = 1) with the coefficients a run's
// step uses (generalized-alpha's or backward Euler's), its amplification matrix and roots: the
// stepping schemes' unit tests measure their frequency and dissipation on it.

#include <cmath>
#include <complex>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "solvers/stepping/GeneralizedAlpha.hpp"

namespace glossa::solvers::test {

// The balance divided by (1 - af) is linear in u1.
inline Eigen::Vector3d oscillatorStep(const GeneralizedAlpha::Step &s, double k, double c, const Eigen::Vector3d &old) {
  const double u0 = old(0), v0 = old(1), a0 = old(2);
  // a1 = c0 (u1 - u0) - c1 v0 - c2 a0 = c0 u1 + aRest; v1 = v0 + vOld a0 + vNew a1.
  const double aRest = -s.c0 * u0 - s.c1 * v0 - s.c2 * a0;
  const double vRest = v0 + s.vOld * a0 + s.vNew * aRest;
  // k u1 + c v1 + newAcceleration a1 + oldAcceleration a0 + oldForces (c v0 + k u0) = 0
  const double lhs = k + c * s.vNew * s.c0 + s.newAcceleration * s.c0;
  const double rhs = -(c * vRest + s.newAcceleration * aRest + s.oldAcceleration * a0 + s.oldForces * (c * v0 + k * u0));
  const double u1 = rhs / lhs;
  const double a1 = s.c0 * u1 + aRest;
  return {u1, v0 + s.vOld * a0 + s.vNew * a1, a1};
}

// The amplification matrix of one step of u'' + omega^2 u = 0 (columns: the steps of the unit states).
inline Eigen::Matrix3d amplification(const GeneralizedAlpha::Step &s, double omega) {
  Eigen::Matrix3d A;
  for (int j = 0; j < 3; ++j) A.col(j) = oscillatorStep(s, omega * omega, 0.0, Eigen::Vector3d::Unit(j));
  return A;
}

// The principal (complex) eigenvalue, and the spectral radius.
inline std::complex<double> principalRoot(const Eigen::Matrix3d &A) {
  const Eigen::EigenSolver<Eigen::Matrix3d> eig(A);
  std::complex<double> best(0.0, 0.0);
  for (int i = 0; i < 3; ++i) {
    const std::complex<double> l = eig.eigenvalues()(i);
    if (l.imag() > best.imag()) best = l;
  }
  return best;
}
inline double spectralRadius(const Eigen::Matrix3d &A) {
  const Eigen::EigenSolver<Eigen::Matrix3d> eig(A);
  return eig.eigenvalues().cwiseAbs().maxCoeff();
}

// T_numerical / T - 1 of a step at Omega = w dt (omega = 1, dt = Omega).
inline double periodError(const GeneralizedAlpha::Step &s) {
  const double discrete = std::arg(principalRoot(amplification(s, 1.0))) / s.dt;
  return 1.0 / discrete - 1.0;
}

} // namespace glossa::solvers::test
