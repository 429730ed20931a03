#pragma once
// The Q1-P0 three-field element with its pressure and dilatation condensed out (doc/theory.md,
// eq. 7). Per element, with Lambda held fixed (augmented Lagrangian):
//   delta p:     theta = (1/V) int J dV              (current over reference volume)
//   delta theta: p = U'(theta) + Lambda
//   delta u:     R_a = int (P_iso + p J F^{-T}) dN_a/dX dV
// and the consistent tangent of the condensed system
//   K = int B^T (A_iso + p d(J F^{-T})/dF) B dV + U''(theta)/V g g^T,   g_a = int J F^{-T} dN_a/dX dV.
// This equals step-44's cell-wise static condensation of its DGPM_0 pressure and dilatation.
// Eigen fixed-size only: no Trilinos, unit-tested alone.

#include <array>

#include <Eigen/Core>

#include "fem/HexShape.hpp"
#include "fem/QuadraturePointLaw.hpp"
#include "materials/IsochoricMaterial.hpp"
#include "materials/VolumetricEnergy.hpp"

namespace glossa::fem {

using ElementVector = Eigen::Matrix<double, 24, 1>; // dof 3*a + i
using ElementMatrix = Eigen::Matrix<double, 24, 24>;

// A nodal matrix as an element vector (dof 3*a + i).
ElementVector flattenNodes(const NodeMatrix &u);

struct Q1P0Result {
  bool valid = false;        // false: J <= 0 at a quadrature point, a degenerate element, or a
                             // point law that failed (lawFailed)
  bool lawFailed = false;
  ElementVector residual = ElementVector::Zero(); // internal force [N]
  ElementMatrix tangent = ElementMatrix::Zero();
  double theta = 1.0;                             // element dilatation v/V
  double pressure = 0.0;                          // p = U'(theta) + Lambda [Pa]
  double referenceVolume = 0.0;
  ElementVector volumeGradient = ElementVector::Zero(); // g = dv/du (the condensed kernels)
  double energy = 0.0;                            // int psi_iso dV + V U(theta) + Lambda V (theta-1)
  double minJ = 1.0;                              // smallest J at the quadrature points
  // Size of the terms that cancel in the residual: |residual| and the volumetric stiffness times
  // the element's area, U''(theta) V^(2/3), whose product with a volume difference of relative
  // round-off epsilon is the residual's round-off floor.
  double forceScale = 0.0;
  Eigen::Matrix3d cauchyMean = Eigen::Matrix3d::Zero(); // (1/v) int sigma dv
};

enum class Q1P0Output { ResidualOnly, ResidualAndTangent };

// What the kernel computes from the displacement and the point law alone, before any pressure:
// every element pass at the same displacement (an Uzawa update changes only Lambda, so the next
// Newton solve's first pass; the muscle history's and the output's passes at a converged state)
// finishes from it (finishQ1P0, finishQ1P0Mixed) without evaluating the point laws or forming
// the element matrices again. With p constant in the element,
//   R = residual + p g,   K = tangent + p volumeHessian + U''(theta)/V g g^T.
struct Q1P0DisplacementPart {
  bool valid = false;       // the kinematics: a regular reference element and J > 0 everywhere
  bool lawFailed = false;   // a point law failed (valid kinematics)
  bool withTangent = false; // tangent and volumeHessian were formed
  double minJ = 1.0;
  double referenceVolume = 0.0, volume = 0.0; // V and v = int J dV
  ElementVector volumeGradient = ElementVector::Zero(); // g = dv/du
  ElementVector residual = ElementVector::Zero();       // int P_iso : grad N dV
  ElementMatrix tangent = ElementMatrix::Zero();        // int B^T A_iso B dV
  // d^2 v / du^2 = int J (n_a,i n_b,k - n_a,k n_b,i) dV with n_a = F^{-T} grad N_a: the
  // pressure's geometric stiffness per unit pressure (the cofactor's derivative, eq. 7).
  ElementMatrix volumeHessian = ElementMatrix::Zero();
  double energy = 0.0;                                   // int psi_iso dV
  Eigen::Matrix3d cauchyIntegral = Eigen::Matrix3d::Zero(); // int P_iso F^T dV
};

// Fills `part` in place (every field it had is replaced).
void evaluateDisplacementPart(const NodeMatrix &X, const NodeMatrix &u, const QuadraturePointLaw &law,
                              Q1P0Output what, Q1P0DisplacementPart &part);
inline Q1P0DisplacementPart evaluateDisplacementPart(const NodeMatrix &X, const NodeMatrix &u,
                                                     const QuadraturePointLaw &law, Q1P0Output what) {
  Q1P0DisplacementPart part;
  evaluateDisplacementPart(X, u, law, what, part);
  return part;
}
// The condensed element (evaluateQ1P0) from its displacement part; `what` may ask the tangent only
// of a part formed with it.
Q1P0Result finishQ1P0(const Q1P0DisplacementPart &part, const materials::VolumetricEnergy &volumetric, double lambda,
                      Q1P0Output what);

// X: reference nodal coordinates; u: nodal displacements; lambda: the element's augmented
// Lagrange multiplier.
Q1P0Result evaluateQ1P0(const NodeMatrix &X, const NodeMatrix &u, const QuadraturePointLaw &law,
                        const materials::VolumetricEnergy &volumetric, double lambda,
                        Q1P0Output what = Q1P0Output::ResidualAndTangent);
inline Q1P0Result evaluateQ1P0(const NodeMatrix &X, const NodeMatrix &u,
                               const materials::IsochoricMaterial &material,
                               const materials::VolumetricEnergy &volumetric, double lambda,
                               Q1P0Output what = Q1P0Output::ResidualAndTangent) {
  return evaluateQ1P0(X, u, UniformPointLaw(material), volumetric, lambda, what);
}

// The three-field Newton iterate of one element (deal.II step-44 style): dilatation theta and
// pressure p are element unknowns updated by the linearised local equations, not recomputed
// exactly from u, which keeps Newton robust for kappa/mu in the thousands. A base is the
// iterate k: (u_k, theta_k, p_k) with the volume linearisation v(u) ~ v_k + g_k . (u - u_k).
// The Newton update from iterate k to a trial u gives
//   theta = (v_k + g_k . (u - u_k)) / V,   p = U'(theta_k) + U''(theta_k)(theta - theta_k) + Lambda,
// and at any iterate the condensed residual is R_u + g (U''(theta) R_p + R_theta) / V with
// R_p = v(u) - theta V and R_theta = V (U'(theta) - p + Lambda), both zero at convergence.
struct MixedBase {
  NodeMatrix u = NodeMatrix::Zero();
  ElementVector g = ElementVector::Zero();
  double v = 0.0;
  double theta = 1.0;
  double pressure = 0.0;
  bool valid = false;
};

// The iterate at u: extrapolated from `previous` by the Newton update above, or, without it,
// consistent (theta = v(u)/V, p = U'(theta) + Lambda).
MixedBase mixedBase(const NodeMatrix &X, const NodeMatrix &u, const MixedBase *previous,
                    const materials::VolumetricEnergy &volumetric, double lambda);

// Residual and tangent with the element state of the iterate: `base`'s own state when
// `extrapolate` is false (u must then be base.u), or the Newton update from `base` to u.
Q1P0Result evaluateQ1P0Mixed(const NodeMatrix &X, const NodeMatrix &u, const MixedBase &base,
                             const QuadraturePointLaw &law, const materials::VolumetricEnergy &volumetric,
                             double lambda, bool extrapolate,
                             Q1P0Output what = Q1P0Output::ResidualAndTangent);
// The same from the displacement part at u.
Q1P0Result finishQ1P0Mixed(const Q1P0DisplacementPart &part, const NodeMatrix &u, const MixedBase &base,
                           const materials::VolumetricEnergy &volumetric, double lambda, bool extrapolate,
                           Q1P0Output what);
inline Q1P0Result evaluateQ1P0Mixed(const NodeMatrix &X, const NodeMatrix &u, const MixedBase &base,
                                    const materials::IsochoricMaterial &material,
                                    const materials::VolumetricEnergy &volumetric, double lambda,
                                    bool extrapolate, Q1P0Output what = Q1P0Output::ResidualAndTangent) {
  return evaluateQ1P0Mixed(X, u, base, UniformPointLaw(material), volumetric, lambda, extrapolate, what);
}

// The same element without the mixed treatment: U(J) at every quadrature point (plain Q1),
// kept to show volumetric locking (Cook's membrane test).
Q1P0Result evaluatePlainQ1(const NodeMatrix &X, const NodeMatrix &u, const QuadraturePointLaw &law,
                           const materials::VolumetricEnergy &volumetric,
                           Q1P0Output what = Q1P0Output::ResidualAndTangent);
inline Q1P0Result evaluatePlainQ1(const NodeMatrix &X, const NodeMatrix &u,
                                  const materials::IsochoricMaterial &material,
                                  const materials::VolumetricEnergy &volumetric,
                                  Q1P0Output what = Q1P0Output::ResidualAndTangent) {
  return evaluatePlainQ1(X, u, UniformPointLaw(material), volumetric, what);
}

// The element's reference volume V, current volume v = int J dV and its gradient
// g_a = dv/du_a = int J F^{-T} dN_a/dX dV: the coupling column of an element pressure in the
// uncondensed (mixed) system. False for a degenerate element or J <= 0 at a quadrature point.
bool elementVolumeGradient(const NodeMatrix &X, const NodeMatrix &u, double &V, double &v, ElementVector &g);

// The deformation gradients and reference volume weights at the 8 quadrature points
// (gaussHex2() order); false for a degenerate reference element. Used to evaluate point laws
// outside an assembly (history updates, output of fibre stretches).
bool quadratureDeformationGradients(const NodeMatrix &X, const NodeMatrix &u, std::array<Eigen::Matrix3d, 8> &F,
                                    std::array<double, 8> &dV);

} // namespace glossa::fem
