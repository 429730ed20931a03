#pragma once
// Isochoric Neo-Hookean: psi_iso = mu/2 (I1-bar - 3), I1-bar = J^{-2/3} tr(F^T F)
// (paper eq. 8; the same split as deal.II step-44, so its results are a direct reference).

#include "materials/IsochoricMaterial.hpp"

namespace glossa::materials {

class NeoHookean final : public IsochoricMaterial {
public:
  explicit NeoHookean(double mu);
  PointResponse evaluate(const Eigen::Matrix3d &F) const override;
  double shearModulus() const override { return mu_; }

private:
  double mu_;
};

} // namespace glossa::materials
