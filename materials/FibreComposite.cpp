#include "materials/FibreComposite.hpp"

#include <cmath>
#include <stdexcept>

namespace glossa::materials {

MatrixStressForm matrixStressFormFromName(const std::string &name) {
  if (name == "in-full") return MatrixStressForm::InFull;
  if (name == "fibre-direction-removed") return MatrixStressForm::FibreDirectionRemoved;
  if (name == "mixture-weighted") return MatrixStressForm::MixtureWeighted;
  throw std::invalid_argument("unknown matrix stress form '" + name +
                              "' (in-full, fibre-direction-removed, mixture-weighted)");
}

const char *matrixStressFormName(MatrixStressForm form) {
  switch (form) {
    case MatrixStressForm::InFull:
      return "in-full";
    case MatrixStressForm::FibreDirectionRemoved:
      return "fibre-direction-removed";
    case MatrixStressForm::MixtureWeighted:
      return "mixture-weighted";
  }
  return "?";
}

double matrixWeight(MatrixStressForm form, double matrixFraction) {
  return form == MatrixStressForm::MixtureWeighted ? matrixFraction : 1.0;
}

FibreStretch fibreStretch(const IsochoricFrame &frame, const Eigen::Vector3d &N) {
  FibreStretch s;
  s.M = N * N.transpose();
  s.I4 = isochoricInvariant(frame, s.M, /*withHessian=*/false);
  s.lambdaBar = std::sqrt(s.I4.value);
  return s;
}

// With psi(lambda), lambda = sqrt(I4):  d psi/d I4 = T / (2 lambda),
// d2 psi/d I4^2 = (dT/dlambda - T/lambda) / (4 lambda^2).
void addFibreResponse(const FibreStretch &s, double phi, const FibreTension &t, FibreTerms &terms) {
  if (phi == 0.0) return;
  const double lambda = s.lambdaBar;
  const double d1 = t.T / (2.0 * lambda);
  const double d2 = (t.dTdLambda - t.T / lambda) / (4.0 * lambda * lambda);
  const Vector9 g = flatten(s.I4.dF);
  PointResponse &r = terms.response;
  r.energy += phi * t.energy;
  r.P += phi * d1 * s.I4.dF;
  r.dPdF.noalias() += (phi * d2) * g * g.transpose();
  terms.hessianWeight += (phi * d1) * s.M;
}

// In Piola form the eq. 5 term is phi h dI4/dF with h = (tau_M : n (x) n) / (2 I4-bar), because
// dev(n (x) n) F^{-T} = dI4/dF / (2 I4-bar). With a = F N:
//   tau_M : n (x) n = q / (a.a),   q = a . P_M F^T a,   so  h = q w,  w = J^{2/3} / (2 (a.a)^2),
//   dw/dF = w (2/3 F^{-T} - 4 a (x) N / (a.a)),
//   dq/dF_mn = ((P F^T + F P^T) a)_m N_n + a_m (P^T a)_n + sum_iJ a_i (F^T a)_J dP_iJ/dF_mn.
void removeMatrixFibreDirectionStress(const IsochoricFrame &frame, const Eigen::Vector3d &N,
                                      const FibreStretch &s, double phi, const PointResponse &matrix,
                                      FibreTerms &terms) {
  if (phi == 0.0) return;
  const Eigen::Matrix3d &F = frame.F;
  const Eigen::Matrix3d &PM = matrix.P;
  const Eigen::Vector3d a = F * N;
  const double aa = a.squaredNorm();
  const Eigen::Vector3d FTa = F.transpose() * a;
  const double q = a.dot(PM * FTa);
  const double w = 1.0 / (frame.Jm23 * 2.0 * aa * aa);  // J^{2/3} / (2 (a.a)^2)
  const double h = q * w;

  Eigen::Matrix3d dq =
      (PM * FTa + F * (PM.transpose() * a)) * N.transpose() + a * (PM.transpose() * a).transpose();
  Vector9 weights;
  for (int i = 0; i < 3; ++i)
    for (int J_ = 0; J_ < 3; ++J_) weights(i * 3 + J_) = a(i) * FTa(J_);
  const Vector9 dqFromP = matrix.dPdF.transpose() * weights;
  const Eigen::Matrix3d dw = w * ((2.0 / 3.0) * frame.FinvT - (4.0 / aa) * a * N.transpose());
  const Vector9 dh = w * (flatten(dq) + dqFromP) + q * flatten(dw);

  terms.response.P -= phi * h * s.I4.dF;
  terms.response.dPdF.noalias() -= phi * flatten(s.I4.dF) * dh.transpose();
  terms.hessianWeight -= (phi * h) * s.M;
}

}  // namespace glossa::materials
