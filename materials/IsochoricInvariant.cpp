#include "materials/IsochoricInvariant.hpp"

#include <Eigen/LU>
#include <cmath>

namespace glossa::materials {

// I = J^{-2/3} I_M, I_M = F M : F.
// dI/dF_iJ = J^{-2/3} (2 (F M)_iJ - 2/3 I_M Finv_Ji)
// d2I/dF_iJ dF_kL = 2 J^{-2/3} [ d_ik M_JL - 2/3 ((F M)_iJ Finv_Lk + Finv_Ji (F M)_kL)
//                                + 2/9 I_M Finv_Ji Finv_Lk + 1/3 I_M Finv_Li Finv_Jk ]
// (for M = 1 this is twice the isochoric Neo-Hookean tangent per unit mu).
IsochoricInvariant isochoricInvariant(const Eigen::Matrix3d &F, const Eigen::Matrix3d &M) {
  const double J = F.determinant();
  const Eigen::Matrix3d Finv = F.inverse();
  const Eigen::Matrix3d FM = F * M;
  const double IM = (FM.array() * F.array()).sum();
  const double Jm23 = std::pow(J, -2.0 / 3.0);

  IsochoricInvariant r;
  r.value = Jm23 * IM;
  r.dF = Jm23 * (2.0 * FM - (2.0 / 3.0) * IM * Finv.transpose());
  const double c = 2.0 * Jm23;
  for (int i = 0; i < 3; ++i)
    for (int J_ = 0; J_ < 3; ++J_)
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L) {
          double v = (i == k) ? M(J_, L) : 0.0;
          v -= 2.0 / 3.0 * (FM(i, J_) * Finv(L, k) + Finv(J_, i) * FM(k, L));
          v += 2.0 / 9.0 * IM * Finv(J_, i) * Finv(L, k);
          v += 1.0 / 3.0 * IM * Finv(L, i) * Finv(J_, k);
          r.d2F(i * 3 + J_, k * 3 + L) = c * v;
        }
  return r;
}

}  // namespace glossa::materials
