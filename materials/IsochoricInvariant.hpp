#pragma once
// Isochoric invariants of C-bar = J^{-2/3} F^T F and their first and second derivatives with
// respect to F (doc/theory.md): I1-bar = tr C-bar (the Fung laws, eq. 9-10) and
// I4-bar = N . C-bar N = lambda-bar_f^2 (the fibre families, eq. 2-6); and I2-bar, the second
// invariant of C-bar (the Mooney-Rivlin laws), from I1-bar and tr(C-bar^2). I1-bar and I4-bar are
// I_M-bar = J^{-2/3} C : M for a symmetric structural tensor M (M = 1 or M = N (x) N), so one
// routine serves both. Any energy psi(I_M-bar) then has P = psi' dI/dF and
// dP/dF = psi'' dI/dF (x) dI/dF + psi' d2I/dF2, insensitive to pure dilatation by construction.

#include <Eigen/Core>

#include "materials/IsochoricMaterial.hpp"

namespace glossa::materials {

struct IsochoricInvariant {
  double value = 0.0;                            // I_M-bar = J^{-2/3} tr(C M)
  Eigen::Matrix3d dF = Eigen::Matrix3d::Zero();  // dI/dF_iJ
  Tangent9 d2F = Tangent9::Zero();               // d2I/dF_iJ dF_kL, row i*3+J, column k*3+L
};

using Vector9 = Eigen::Matrix<double, 9, 1>;

// A 3x3 tensor as the 9-vector matching Tangent9's index i*3+J.
inline Vector9 flatten(const Eigen::Matrix3d &A) {
  Vector9 v;
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J) v(i * 3 + J) = A(i, J);
  return v;
}

// What every invariant at one F shares, computed once per point: F^-T and J^{-2/3}.
// Requires det F > 0.
struct IsochoricFrame {
  explicit IsochoricFrame(const Eigen::Matrix3d &F);
  Eigen::Matrix3d F, FinvT;
  double Jm23;
};

// Requires M symmetric. Without the Hessian d2F stays zero.
IsochoricInvariant isochoricInvariant(const IsochoricFrame &frame, const Eigen::Matrix3d &M, bool withHessian = true);
// Requires det F > 0 and M symmetric.
inline IsochoricInvariant isochoricInvariant(const Eigen::Matrix3d &F, const Eigen::Matrix3d &M) {
  return isochoricInvariant(IsochoricFrame(F), M);
}

// d2 += weight d2I_M-bar/dF2. The Hessian is linear in M, so one call with M = sum_f w_f M_f adds
// sum_f w_f d2I_f/dF2: a composite with several fibre families builds it once per point, not once
// per family. Requires M symmetric.
void addIsochoricHessian(const IsochoricFrame &frame, const Eigen::Matrix3d &M, double weight, Tangent9 &d2);

// I1-bar (M = 1).
inline IsochoricInvariant isochoricI1(const Eigen::Matrix3d &F) {
  return isochoricInvariant(F, Eigen::Matrix3d::Identity());
}

// I4-bar = lambda-bar_f^2 for the reference fibre direction N (M = N (x) N).
inline IsochoricInvariant isochoricI4(const Eigen::Matrix3d &F, const Eigen::Vector3d &N) {
  return isochoricInvariant(F, N * N.transpose());
}

// I2-bar = 1/2 (I1-bar^2 - tr(C-bar^2)), the second invariant of C-bar (the Mooney-Rivlin laws).
// Requires det F > 0.
IsochoricInvariant isochoricI2(const Eigen::Matrix3d &F);

}  // namespace glossa::materials
