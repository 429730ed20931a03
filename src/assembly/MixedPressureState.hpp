#pragma once
// The element pressures as unknowns of the Newton solve (Incompressibility/method = mixed): the
// uncondensed Q1-P0 system
//   [ K  B^T ] [du]   [ -R_u          ]
//   [ B  -C  ] [dp] = [ -(v - V theta_phys(p)) ]
// per element e, with K the tangent at fixed pressure (the kernel's volumetric energy is zero, so
// the element pressure is the multiplier Lambda_e = p_e), B_e = dv_e/du, and C_e = V_e / U''(theta)
// at theta = theta_phys(p_e), the material's compliance (0 for kappa = inf: exact incompressibility,
// which the condensed form cannot express). Eliminating dp element by element gives back the
// condensed three-field Newton step, so both give the same iterates (doc/incompressibility.md).
//
// The model evaluator makes the scaled pressures p~_e = p_e / sigma_e unknowns beside the
// displacements (a product space) and linearises this state at every evaluation; the block
// solver reads its blocks.

#include <vector>

#include "assembly/Assembler.hpp"
#include "materials/VolumetricEnergy.hpp"

namespace glossa::assembly {

struct MixedPressureState {
  MixedPressureState(materials::VolumetricEnergy physicalLaw, double mu) : physical(physicalLaw), shearModulus(mu) {}

  materials::VolumetricEnergy physical; // the material's law (kappa may be inf), and theta_phys(p)
  double shearModulus;

  // The blocks at the last tangent (linearise), with the pressure unknown and its equation scaled
  // by sigma_e = mu / V_e^(1/3): B ~ h^2 and M_p / mu ~ h^3 / mu against K ~ mu h would leave the
  // pressure rows 1e-11 of the displacement rows (SI units, 1 mm elements), and GMRES would stop
  // before it had touched them. Scaled, every block is of the size mu h.
  PressureCoupling coupling;               // its volumeGradient holds sigma B
  Teuchos::RCP<Vector> compliance;         // sigma_e^2 C_e
  Teuchos::RCP<Vector> schurDiagonal;      // sigma_e^2 (C_e + V_e / mu): minus the Schur-complement approximation
  Teuchos::RCP<Vector> constraintResidual; // sigma_e (v_e - V_e theta_phys(p_e))

  // sigma_e per local element (it depends on the reference volume alone), as a vector too, and
  // sum_e (sigma_e V_e)^2 over the local elements: the size of the pressure rows' terms.
  std::vector<double> sigma;
  Teuchos::RCP<Vector> pressureScale;
  double constraintTerms = 0.0;

  // The scales, once, before the first linearisation. Collective.
  void initialise(const Assembler &assembler);
  // Forms the blocks at displacement u and element pressures p (local elements). Collective.
  void linearise(const Assembler &assembler, const Vector &u, const std::vector<double> &pressure);
};

} // namespace glossa::assembly
