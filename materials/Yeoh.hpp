#pragma once
// Uncoupled Yeoh law psi = C10 (I1b - 3) + C20 (I1b - 3)^2 + C30 (I1b - 3)^3, I1b = tr C-bar:
// a polynomial in I1b alone, fitted to soft tissue and rubber where the stiffening at large
// stretch matters (C20 is often negative). Small-strain shear modulus mu = 2 C10.

#include "materials/IsochoricMaterial.hpp"

namespace glossa::materials {

class Yeoh final : public IsochoricMaterial {
public:
  // C10 > 0, C20 and C30 finite; else std::invalid_argument naming the coefficient.
  Yeoh(double C10, double C20, double C30);

  PointResponse evaluate(const Eigen::Matrix3d &F) const override;
  double shearModulus() const override { return 2.0 * C10_; }
  double C10() const { return C10_; }
  double C20() const { return C20_; }
  double C30() const { return C30_; }

private:
  double C10_, C20_, C30_;
};

} // namespace glossa::materials
