#pragma once
// What an element's internal force and tangent gain after its kernel, inside the assembly pass:
// the energy-conserving step's discrete gradient (solvers/run/EnergyConservingForces,
// doc/dynamics.md), which needs each element's own force and stored energy at the trial
// displacement, not only the assembled sum. Plain Eigen: no Trilinos.

#include <cstddef>

#include "fem/Q1P0Element.hpp"
#include "materials/VolumetricEnergy.hpp"

namespace glossa::assembly {

class ElementForceCorrection {
public:
  virtual ~ElementForceCorrection() = default;
  // Local element i at displacement ue with multiplier lambda and the volumetric law its kernel
  // used, the kernel's result r: adds to the element force re and, if given, the tangent ke
  // (before the constrained dofs are zeroed).
  virtual void add(std::size_t localElement, const fem::NodeMatrix &ue, double lambda,
                   const materials::VolumetricEnergy &volumetric, const fem::Q1P0Result &r, fem::ElementVector &re,
                   fem::ElementMatrix *ke) const = 0;
};

} // namespace glossa::assembly
