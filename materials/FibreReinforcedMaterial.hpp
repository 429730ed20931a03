#pragma once
// A fibre-reinforced isochoric material (doc/theory.md, eq. 2-6): a matrix law (e.g. the Fung
// muscle matrix, eq. 10) and any number of fibre families, each a reference direction N_f with a
// volume fraction phi_f and a passive fibre law psi_f(lambda-bar_f) (e.g. the parallel element,
// eq. 17). Fibres resist tension only: a family with lambda-bar_f <= 1 adds nothing.
// The Kirchhoff stress form (eq. 6 by default, eq. 5 or the literal mixture as options) is
// described in FibreComposite.hpp and doc/materials.md.

#include <memory>
#include <vector>

#include "materials/FibreComposite.hpp"
#include "materials/FibreFamily.hpp"
#include "materials/FibreLaw.hpp"
#include "materials/IsochoricMaterial.hpp"

namespace glossa::materials {

class FibreReinforcedMaterial final : public IsochoricMaterial {
 public:
  // Throws std::invalid_argument on a null matrix or fibre law or invalid families.
  FibreReinforcedMaterial(std::shared_ptr<const IsochoricMaterial> matrix, std::vector<FibreFamily> families,
                          std::shared_ptr<const FibreLaw> fibre,
                          MatrixStressForm form = MatrixStressForm::InFull);

  PointResponse evaluate(const Eigen::Matrix3d &F) const override;
  // The small-strain shear modulus of the weighted matrix (tension-only fibres add no stiffness
  // at F = 1 in compression, so the matrix sets the scale of the incompressibility penalty).
  double shearModulus() const override;

  double matrixFraction() const { return matrixFraction_; }  // phi_M = 1 - sum phi_f
  const std::vector<FibreFamily> &families() const { return families_; }
  MatrixStressForm stressForm() const { return form_; }

 private:
  std::shared_ptr<const IsochoricMaterial> matrix_;
  std::vector<FibreFamily> families_;
  std::shared_ptr<const FibreLaw> fibre_;
  MatrixStressForm form_;
  double matrixFraction_;
};

}  // namespace glossa::materials
