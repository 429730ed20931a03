#pragma once
// Assembly of a fibre-reinforced point response from its matrix and fibre parts
// (eq. 2-6, doc/materials.md), shared by FibreReinforcedMaterial (passive fibres) and
// MuscleMaterial (Hill fibres). Fibre stretch uses the isochoric C-bar:
// lambda-bar_f = sqrt(N_f . C-bar N_f) = sqrt(I4-bar).
//
// Kirchhoff stress forms (the choice is documented in doc/materials.md):
//  - InFull (eq. 6, the paper's choice, default): tau = tau_M + sum_f phi_f tau_f. The matrix
//    stress is kept in full (not weighted by phi_M), also its fibre-direction part; the
//    potential is psi_M + sum_f phi_f psi_f.
//  - FibreDirectionRemoved (eq. 5): as eq. 6 minus sum_f phi_f dev[(tau_M : n_f (x) n_f)
//    n_f (x) n_f], the matrix stress along each fibre replaced by the fibre's (the rule of
//    mixtures with fibres carrying transverse and shear loads like the matrix). Not derivable
//    from a potential: the tangent is not symmetric; `energy` then reports eq. 6's potential.
//  - MixtureWeighted (eq. 2 and 4 literally, axial-only fibres): tau = phi_M tau_M + sum_f
//    phi_f tau_f, potential phi_M psi_M + sum_f phi_f psi_f.
// Each fibre adds tau_f = lambda-bar_f psi_f' dev(n_f (x) n_f) with n_f = F-bar N_f / lambda-bar_f,
// the derivative of psi_f(lambda-bar_f(F)), so that every isochoric stress stays deviatoric and
// the element pressure is the mean stress (the paper writes eq. 6 without dev; the difference is
// a pressure, absorbed by p in the incompressible limit).

#include <Eigen/Core>
#include <string>

#include "materials/FibreLaw.hpp"
#include "materials/IsochoricInvariant.hpp"
#include "materials/IsochoricMaterial.hpp"

namespace glossa::materials {

enum class MatrixStressForm { InFull, FibreDirectionRemoved, MixtureWeighted };

// "in-full" (eq. 6), "fibre-direction-removed" (eq. 5), "mixture-weighted" (eq. 2/4).
MatrixStressForm matrixStressFormFromName(const std::string &name);
const char *matrixStressFormName(MatrixStressForm form);

// Weight of the matrix response in the composite: phi_M for MixtureWeighted, else 1.
double matrixWeight(MatrixStressForm form, double matrixFraction);

// Fibre stretch lambda-bar = sqrt(I4-bar) and the first derivative of I4-bar (its Hessian is
// added once per point by FibreTerms::addTo).
struct FibreStretch {
  double lambdaBar = 1.0;
  IsochoricInvariant I4;  // value and dF; d2F left zero
  Eigen::Matrix3d M;      // the structural tensor N (x) N
};
FibreStretch fibreStretch(const IsochoricFrame &frame, const Eigen::Vector3d &N);

// The fibre and eq. 5 terms of a composite point response. Each term c_f d2I4-bar_f/dF2 is kept as
// its weight c_f on N_f (x) N_f: the Hessian is linear in the structural tensor, so addTo builds
// all of them with one addIsochoricHessian call instead of one per family.
struct FibreTerms {
  PointResponse response;                                    // all but the I4-bar Hessian terms
  Eigen::Matrix3d hessianWeight = Eigen::Matrix3d::Zero();  // sum_f c_f N_f (x) N_f
  // r += response and sum_f c_f d2I4-bar_f/dF2, for any response with energy, P and dPdF.
  template <class Response>
  void addTo(const IsochoricFrame &frame, Response &r) const {
    r.energy += response.energy;
    r.P += response.P;
    r.dPdF += response.dPdF;
    if (!hessianWeight.isZero(0.0)) addIsochoricHessian(frame, hessianWeight, 1.0, r.dPdF);
  }
};

// terms += phi psi_f, P += phi T d lambda-bar/dF, dP/dF += phi d(T d lambda-bar/dF)/dF for a fibre
// with tension T(lambda-bar) and stiffness dT/dlambda-bar (both at the current lambda-bar).
void addFibreResponse(const FibreStretch &s, double phi, const FibreTension &t, FibreTerms &terms);

// Eq. 5: terms -= phi_f dev[(tau_M : n (x) n) n (x) n] F^{-T} and its derivative, where tau_M and
// its derivative come from `matrix` (the full, unweighted matrix response at F).
void removeMatrixFibreDirectionStress(const IsochoricFrame &frame, const Eigen::Vector3d &N,
                                      const FibreStretch &s, double phi, const PointResponse &matrix,
                                      FibreTerms &terms);

}  // namespace glossa::materials
