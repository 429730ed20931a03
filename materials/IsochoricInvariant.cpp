#include "materials/IsochoricInvariant.hpp"

#include <Eigen/LU>
#include <cmath>

namespace glossa::materials {

// I = J^{-2/3} I_M, I_M = F M : F.
// dI/dF_iJ = J^{-2/3} (2 (F M)_iJ - 2/3 I_M Finv_Ji)
// d2I/dF_iJ dF_kL = 2 J^{-2/3} [ d_ik M_JL - 2/3 ((F M)_iJ Finv_Lk + Finv_Ji (F M)_kL)
//                                + 2/9 I_M Finv_Ji Finv_Lk + 1/3 I_M Finv_Li Finv_Jk ]
// (for M = 1 this is twice the isochoric Neo-Hookean tangent per unit mu).
namespace {
// The bracket above times c, added to d2: outer products of a = FM and b = F^-T (flattened),
// plus the 3x3 blocks (i, k) of d_ik M and Finv_Li Finv_Jk = (F^-T)_iL (F^-T)_kJ.
void addHessian(const Eigen::Matrix3d &FinvT, const Eigen::Matrix3d &FM, double IM, const Eigen::Matrix3d &M,
                double c, Tangent9 &d2) {
  // One pass over the 81 entries, row (i, J) and column (k, L) = 3 i + J and 3 k + L: Eigen formed
  // each outer product and each block as its own pass (5.7 % of a muscle block's instructions).
  const Vector9 a = flatten(FM), b = flatten(FinvT);
  const double cab = -2.0 / 3.0 * c, cbb = 2.0 / 9.0 * c * IM, cblock = 1.0 / 3.0 * c * IM;
  for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L) {
      const int col = 3 * k + L;
      // c [-2/3 (a_row b_col + b_row a_col) + 2/9 I_M b_row b_col], by a_row and b_row
      const double aCoefficient = cab * b(col), bCoefficient = cab * a(col) + cbb * b(col);
      for (int i = 0; i < 3; ++i) {
        const double finvIL = cblock * FinvT(i, L);
        for (int J = 0; J < 3; ++J) {
          const int row = 3 * i + J;
          double v = a(row) * aCoefficient + b(row) * bCoefficient + finvIL * FinvT(k, J);
          if (i == k) v += c * M(J, L);
          d2(row, col) += v;
        }
      }
    }
}
}  // namespace

IsochoricFrame::IsochoricFrame(const Eigen::Matrix3d &F_)
    : F(F_), FinvT(F_.inverse().transpose()), Jm23(std::pow(F_.determinant(), -2.0 / 3.0)) {}

IsochoricInvariant isochoricInvariant(const IsochoricFrame &frame, const Eigen::Matrix3d &M, bool withHessian) {
  const Eigen::Matrix3d FM = frame.F * M;
  const double IM = (FM.array() * frame.F.array()).sum();
  IsochoricInvariant r;
  r.value = frame.Jm23 * IM;
  r.dF = frame.Jm23 * (2.0 * FM - (2.0 / 3.0) * IM * frame.FinvT);
  if (withHessian) addHessian(frame.FinvT, FM, IM, M, 2.0 * frame.Jm23, r.d2F);
  return r;
}

void addIsochoricHessian(const IsochoricFrame &frame, const Eigen::Matrix3d &M, double weight, Tangent9 &d2) {
  const Eigen::Matrix3d FM = frame.F * M;
  addHessian(frame.FinvT, FM, (FM.array() * frame.F.array()).sum(), M, weight * 2.0 * frame.Jm23, d2);
}

// K = tr(C-bar^2) = J^{-4/3} T, T = tr(C^2) = C : C.
// dT/dF_iJ = 4 (F C)_iJ;  d2T/dF_iJ dF_kL = 4 (d_ik C_LJ + F_iL F_kJ + B_ik d_JL), B = F F^T.
// dK/dF_iJ = J^{-4/3} (dT_iJ - 4/3 T Finv_Ji)
// d2K = J^{-4/3} [ d2T - 4/3 (dT_iJ Finv_Lk + Finv_Ji dT_kL) + 16/9 T Finv_Ji Finv_Lk
//                  + 4/3 T Finv_Li Finv_Jk ]
// and I2-bar = 1/2 (I1-bar^2 - K): dI2 = I1 dI1 - dK/2, d2I2 = dI1 (x) dI1 + I1 d2I1 - d2K/2.
IsochoricInvariant isochoricI2(const Eigen::Matrix3d &F) {
  const double J = F.determinant();
  const Eigen::Matrix3d Finv = F.inverse();
  const Eigen::Matrix3d C = F.transpose() * F;
  const Eigen::Matrix3d B = F * F.transpose();
  const Eigen::Matrix3d dT = 4.0 * F * C;
  const double T = (C.array() * C.array()).sum();
  const double Jm43 = std::pow(J, -4.0 / 3.0);

  const IsochoricInvariant I1 = isochoricI1(F);
  const Vector9 g1 = flatten(I1.dF);
  IsochoricInvariant r;
  const double K = Jm43 * T;
  r.value = 0.5 * (I1.value * I1.value - K);
  const Eigen::Matrix3d dK = Jm43 * (dT - (4.0 / 3.0) * T * Finv.transpose());
  r.dF = I1.value * I1.dF - 0.5 * dK;
  Tangent9 d2K;
  for (int i = 0; i < 3; ++i)
    for (int J_ = 0; J_ < 3; ++J_)
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L) {
          double v = 4.0 * ((i == k ? C(L, J_) : 0.0) + F(i, L) * F(k, J_) + (J_ == L ? B(i, k) : 0.0));
          v -= 4.0 / 3.0 * (dT(i, J_) * Finv(L, k) + Finv(J_, i) * dT(k, L));
          v += 16.0 / 9.0 * T * Finv(J_, i) * Finv(L, k);
          v += 4.0 / 3.0 * T * Finv(L, i) * Finv(J_, k);
          d2K(i * 3 + J_, k * 3 + L) = Jm43 * v;
        }
  r.d2F = g1 * g1.transpose() + I1.value * I1.d2F - 0.5 * d2K;
  return r;
}

}  // namespace glossa::materials
