#pragma once
// The element part of the energy-conserving step (Time/integrator = energy conserving,
// doc/dynamics.md): the trapezoidal rule (generalized-alpha at rho_inf = 1), whose element forces
// are the mean of the step's two ends, with each element's force corrected by Gonzalez's discrete
// gradient (fem/DiscreteGradient) so that its work over the step equals its stored energy's
// change. With the trapezoidal rule's inertia, M (a_n + a_{n+1})/2 = M (v_{n+1} - v_n)/dt and
// (u_{n+1} - u_n)/dt = (v_n + v_{n+1})/2, the kinetic energy then changes by exactly minus the
// stored energy's change: their sum is conserved to the solver's tolerance, however stiff or
// nonlinear the element (the trapezoidal rule alone lets the volumetric modes of a nearly
// incompressible solid gain energy until the run fails).
//
// The element force the Newton solve balances is f = f_iso + (U_t'(theta) + Lambda) g (g = dv/du,
// U_t the tangent's volumetric law, Lambda the augmented Lagrange multiplier), the gradient of
// W(u; Lambda) = int psi_iso dV + V (U_t(theta) + Lambda (theta - 1)). A step takes both its ends
// in one potential, W(.; Lambda_mid) with Lambda_mid = (Lambda_n + Lambda)/2, Lambda the Uzawa
// loop's multiplier for the step's end: the multiplier then weighs on the step's force as in the
// trapezoidal rule ((Lambda_n g(u_n) + Lambda g(u_{n+1}))/2), the weight the loop's update assumes
// (with Lambda at both ends it doubles, and the loop needs six times the iterations), and the
// potential's change over the step is exact. Leaving the multiplier's part in the trapezoidal
// form instead does not conserve: the pressure's work along the step's straight path in nodal
// space misses the volume's cubic variation there, and the nearly incompressible cantilever's
// energy doubles within three periods as with the trapezoidal rule. Over the run the conserved
// sum is the kinetic energy, int psi_iso dV + V U_t(theta) and the trapezoidal integral of
// Lambda d theta, whose integrand is at convergence U'(theta) - U_t'(theta), nearly linear: the
// physical energy int psi_iso dV + V U(theta), to the loop's tolerance. Should the loop raise
// U_t's modulus within a step, u_n's force and energy are taken with the new law (from their
// isochoric parts and u_n's dilatation and volume gradient). Elements with muscle fibres keep
// the trapezoidal forces: their active stress and contractile history store no energy to
// conserve. Plain numbers: no Trilinos.

#include <cstddef>
#include <vector>

#include "assembly/ElementForceCorrection.hpp"

namespace glossa::solvers {

class EnergyConservingForces : public assembly::ElementForceCorrection {
public:
  // `corrected`: per local element, whether its force is corrected; `weight`: the scale of the
  // element forces in the step's residual (1 / (1 - alpha_f) = 2: the residual is divided by
  // the weight 1/2 both ends carry).
  EnergyConservingForces(std::vector<char> corrected, double weight);

  // The committed state u_n of local element i (displacement ue), with its multiplier, the
  // kernel's result there (exact condensation) and the volumetric law it used.
  void record(std::size_t localElement, const fem::NodeMatrix &ue, double lambda, const fem::Q1P0Result &r,
              const materials::VolumetricEnergy &volumetric);
  bool corrects(std::size_t localElement) const { return corrected_[localElement] != 0; }

  void add(std::size_t localElement, const fem::NodeMatrix &ue, double lambda,
           const materials::VolumetricEnergy &volumetric, const fem::Q1P0Result &r, fem::ElementVector &re,
           fem::ElementMatrix *ke) const override;

private:
  struct Committed {
    fem::NodeMatrix u = fem::NodeMatrix::Zero();
    fem::ElementVector isochoricForce = fem::ElementVector::Zero(); // f - p g
    fem::ElementVector volumeGradient = fem::ElementVector::Zero(); // g = dv/du
    double isochoricEnergy = 0.0;                                   // int psi_iso dV
    double referenceVolume = 0.0, theta = 1.0;
    double tangentPressure = 0.0; // U_t'(theta) of the law at commit (the step's committed part holds it)
    double lambda = 0.0;          // Lambda_n
  };
  std::vector<char> corrected_;
  double weight_;
  std::vector<Committed> committed_;
};

} // namespace glossa::solvers
