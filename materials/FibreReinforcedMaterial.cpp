#include "materials/FibreReinforcedMaterial.hpp"

#include <stdexcept>
#include <utility>

namespace glossa::materials {

FibreReinforcedMaterial::FibreReinforcedMaterial(std::shared_ptr<const IsochoricMaterial> matrix,
                                                 std::vector<FibreFamily> families,
                                                 std::shared_ptr<const FibreLaw> fibre, MatrixStressForm form)
    : matrix_(std::move(matrix)),
      families_(std::move(families)),
      fibre_(std::move(fibre)),
      form_(form),
      matrixFraction_(validateFibreFamilies(families_)) {
  if (!matrix_) throw std::invalid_argument("FibreReinforcedMaterial: matrix law is null");
  if (!fibre_) throw std::invalid_argument("FibreReinforcedMaterial: fibre law is null");
}

double FibreReinforcedMaterial::shearModulus() const {
  return matrixWeight(form_, matrixFraction_) * matrix_->shearModulus();
}

PointResponse FibreReinforcedMaterial::evaluate(const Eigen::Matrix3d &F) const {
  const PointResponse matrix = matrix_->evaluate(F);
  const double wM = matrixWeight(form_, matrixFraction_);
  PointResponse r;
  r.energy = wM * matrix.energy;
  r.P = wM * matrix.P;
  r.dPdF = wM * matrix.dPdF;
  const IsochoricFrame frame(F);
  FibreTerms fibres;
  for (const FibreFamily &family : families_) {
    const FibreStretch s = fibreStretch(frame, family.N);
    if (form_ == MatrixStressForm::FibreDirectionRemoved)
      removeMatrixFibreDirectionStress(frame, family.N, s, family.volumeFraction, matrix, fibres);
    if (s.lambdaBar <= 1.0) continue;  // tension only
    addFibreResponse(s, family.volumeFraction, fibre_->evaluate(s.lambdaBar), fibres);
  }
  fibres.addTo(frame, r);
  return r;
}

}  // namespace glossa::materials
