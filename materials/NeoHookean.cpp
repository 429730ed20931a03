#include "materials/NeoHookean.hpp"

#include <cmath>
#include <stdexcept>

namespace glossa::materials {

NeoHookean::NeoHookean(double mu) : mu_(mu) {
  if (!(mu > 0.0)) throw std::invalid_argument("NeoHookean: shear modulus must be > 0");
}

PointResponse NeoHookean::evaluate(const Eigen::Matrix3d &F) const {
  const double J = F.determinant();
  const Eigen::Matrix3d Finv = F.inverse();
  const Eigen::Matrix3d FinvT = Finv.transpose();
  const double I1 = F.squaredNorm(); // tr(F^T F)
  const double Jm23 = std::pow(J, -2.0 / 3.0);

  PointResponse r;
  r.energy = 0.5 * mu_ * (Jm23 * I1 - 3.0);
  // P = mu J^{-2/3} (F - I1/3 F^{-T})
  r.P = mu_ * Jm23 * (F - (I1 / 3.0) * FinvT);
  // dP_iJ/dF_kL = mu J^{-2/3} [ d_ik d_JL - 2/3 F_iJ Finv_Lk - 2/3 Finv_Ji F_kL
  //                              + 2/9 I1 Finv_Ji Finv_Lk + 1/3 I1 Finv_Li Finv_Jk ]
  // with the flattened f = vec(F), g = vec(F^{-T}) the first four terms are outer products.
  const double c = mu_ * Jm23;
  Eigen::Matrix<double, 9, 1> f, g;
  for (int i = 0; i < 3; ++i)
    for (int J_ = 0; J_ < 3; ++J_) {
      f(i * 3 + J_) = F(i, J_);
      g(i * 3 + J_) = Finv(J_, i);
    }
  r.dPdF = Tangent9::Identity() - 2.0 / 3.0 * (f * g.transpose() + g * f.transpose()) +
           2.0 / 9.0 * I1 * g * g.transpose();
  for (int i = 0; i < 3; ++i)
    for (int J_ = 0; J_ < 3; ++J_)
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L) r.dPdF(i * 3 + J_, k * 3 + L) += I1 / 3.0 * Finv(L, i) * Finv(J_, k);
  r.dPdF *= c;
  return r;
}

} // namespace glossa::materials
