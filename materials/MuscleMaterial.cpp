#include "materials/MuscleMaterial.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace glossa::materials {

namespace {
double validatedMatrixFraction(const std::vector<MuscleMaterial::Family> &families) {
  if (families.size() > static_cast<std::size_t>(kMaxFibreFamilies))
    throw std::invalid_argument("MuscleMaterial: at most " + std::to_string(kMaxFibreFamilies) +
                                " fibre families per point");
  std::vector<FibreFamily> geometry;
  for (const auto &f : families) geometry.push_back(f.geometry);
  return validateFibreFamilies(geometry);
}
}  // namespace

MuscleMaterial::MuscleMaterial(std::shared_ptr<const IsochoricMaterial> matrix, std::vector<Family> families,
                               MatrixStressForm form)
    : matrix_(std::move(matrix)),
      families_(std::move(families)),
      form_(form),
      matrixFraction_(validatedMatrixFraction(families_)) {
  if (!matrix_) throw std::invalid_argument("MuscleMaterial: matrix law is null");
}

MusclePointResponse MuscleMaterial::evaluate(const MusclePointInput &in) const {
  MusclePointResponse r;
  const int n = familyCount();
  r.lambdaC = in.lambdaCOld;
  r.lambdaF = FamilyValues::Ones(n);
  r.T = FamilyValues::Zero(n);
  r.dLambdaCdLambdaF = FamilyValues::Constant(n, std::numeric_limits<double>::quiet_NaN());
  const bool ownDirections = in.directions.cols() == 0;
  if (in.alpha.size() != n || in.lambdaCOld.size() != n || (!ownDirections && in.directions.cols() != n) ||
      !(in.F.determinant() > 0.0)) {
    r.status = HillSolveStatus::InvalidInput;
    r.failedFamily = n;  // not a family: the point input itself
    return r;
  }

  const PointResponse matrix = matrix_->evaluate(in.F);
  const double wM = matrixWeight(form_, matrixFraction_);
  r.energy = wM * matrix.energy;
  r.P = wM * matrix.P;
  r.dPdF = wM * matrix.dPdF;
  bool anyTaut = false;
  const IsochoricFrame frame(in.F);
  FibreTerms fibres;  // accumulates the fibre and eq. 5 terms
  for (int f = 0; f < n; ++f) {
    const Family &family = families_[f];
    const Eigen::Vector3d N = ownDirections ? family.geometry.N : Eigen::Vector3d(in.directions.col(f));
    const FibreStretch s = fibreStretch(frame, N);
    double start = in.lambdaCStart.size() == n ? in.lambdaCStart(f) : std::numeric_limits<double>::quiet_NaN();
    if (in.lambdaFAtStart.size() == n && in.startSlope.size() == n) {
      const double predicted = start + in.startSlope(f) * (s.lambdaBar - in.lambdaFAtStart(f));
      if (std::isfinite(predicted)) start = predicted;
    }
    const HillFibreResponse h = family.fibre.evaluate({s.lambdaBar, in.alpha(f), in.dt, in.lambdaCOld(f), start});
    if (!succeeded(h.status)) {
      r.status = h.status;
      r.failedFamily = f;
      return r;
    }
    anyTaut = anyTaut || h.status != HillSolveStatus::Slack;
    r.lambdaC(f) = h.lambdaC;
    r.lambdaF(f) = s.lambdaBar;
    r.T(f) = h.T;
    r.dLambdaCdLambdaF(f) = h.dLambdaCdLambdaF;
    const double phi = family.geometry.volumeFraction;
    if (form_ == MatrixStressForm::FibreDirectionRemoved)
      removeMatrixFibreDirectionStress(frame, N, s, phi, matrix, fibres);
    addFibreResponse(s, phi, {h.storedEnergy, h.T, h.dTdLambdaF}, fibres);
  }
  fibres.addTo(frame, r);
  r.status = anyTaut || n == 0 ? HillSolveStatus::Taut : HillSolveStatus::Slack;
  return r;
}

}  // namespace glossa::materials
