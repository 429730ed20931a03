#pragma once
// What a dynamic run adds to the quasi-static problem f = f_int - f_ext and its tangent: the
// time integrator's inertia, damping and the last step's forces at a trial displacement
// (solvers/run/Inertia, generalized-alpha). The model evaluator asks for it after each assembly,
// so Newton, the Uzawa loop and the linear solvers see the dynamic balance unchanged.

#include "assembly/ElementForceCorrection.hpp"
#include "assembly/TpetraTypes.hpp"

namespace glossa::assembly {

class InertiaTerm {
public:
  virtual ~InertiaTerm() = default;
  // A step of size dt from the committed state begins (every solve of it, a retry's too).
  virtual void beginStep(double dt) = 0;
  // f += the dynamic terms at the owned displacement u (nothing at constrained dofs) and
  // K += their derivative (K assembled, on the Assembler's graph); either may be null. Collective.
  virtual void addTo(const Vector &u, Vector *f, FEMatrix *K) const = 0;
  // What the integrator adds to each element's force inside the assembly (the energy-conserving
  // step's discrete gradient), or null.
  virtual const ElementForceCorrection *elementCorrection() const { return nullptr; }
};

} // namespace glossa::assembly
