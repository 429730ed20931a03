#pragma once
// Uncoupled Mooney-Rivlin law in its five-parameter form,
//   psi = C10 (I1b - 3) + C01 (I2b - 3) + C11 (I1b - 3)(I2b - 3) + C20 (I1b - 3)^2 + C02 (I2b - 3)^2
// with I1b, I2b the invariants of C-bar = J^{-2/3} C. C10 and C01 alone: the two-parameter law
// (FEBio's "Mooney-Rivlin", its verification case mi03: C10 = 1, C01 = 10); C10 = 1037 Pa and
// C20 = 486 Pa: the ArtiSynth tongue's material. The volumetric part is the element's
// (VolumetricEnergy), as for every isochoric law. Small-strain shear modulus mu = 2 (C10 + C01).

#include "materials/IsochoricMaterial.hpp"

namespace glossa::materials {

struct MooneyRivlinParameters {
  double C10 = 0.0, C01 = 0.0, C11 = 0.0, C20 = 0.0, C02 = 0.0; // [Pa]
};

class MooneyRivlin final : public IsochoricMaterial {
public:
  // Every coefficient finite and C10 + C01 > 0 (a positive small-strain shear modulus); else
  // std::invalid_argument naming the coefficient.
  explicit MooneyRivlin(const MooneyRivlinParameters &c);
  static MooneyRivlin artisynthTongue(); // C10 = 1037 Pa, C20 = 486 Pa

  PointResponse evaluate(const Eigen::Matrix3d &F) const override;
  double shearModulus() const override { return 2.0 * (c_.C10 + c_.C01); }
  const MooneyRivlinParameters &parameters() const { return c_; }

private:
  MooneyRivlinParameters c_;
};

} // namespace glossa::materials
