#pragma once
// The tangent's stiffness along the load path at a converged state, for the limit-point check
// after each step (LimitPointMonitor). The path u(t) of f(u(t), t) = 0 has the tangent
//   du/dt = -K^-1 df/dt,   K = df/du at the converged u, time and multipliers,
// and the stiffness along it, s = u'^T K u' / u'^T u' = -(df/dt)^T u' / u'^T u', is positive
// while K is positive definite and turns negative past a limit point, where K has lost it along
// the path (the chord between two converged states does not show this: across a jump to the
// other branch it is not isochoric, and the augmented-Lagrangian penalty makes it look stiff).
// df/dt at fixed u is a central difference in time of the residual (loads, follower ones too,
// and prescribed displacements); activation changes no load in it, so a path driven by muscle
// activation alone has df/dt = 0 and no measurement.

#include <string>
#include <vector>

#include "assembly/Assembler.hpp"

namespace glossa::solvers {

class NewtonSolver;

struct PathStiffness {
  double stiffness; // s [N/m per m^2 of dof motion]; NaN: not measured (df/dt = 0, or the solve failed)
  int krylovIterations = 0;
  std::string note; // why not measured, if it should have been
};

// At the converged u of the step to `time` (of size dt) with `lambda`; the model evaluator
// behind `newton` must be at that time and multipliers. One tangent assembly and solve, with
// Newton's kept linear solver, or with a solver of its own (`ownSolver`: a tangent other than the
// one Newton factored or preconditioned, ConstrainedTangent's). Collective.
PathStiffness pathStiffness(const assembly::Assembler &assembler, const NewtonSolver &newton, const assembly::Vector &u,
                            double time, double dt, const std::vector<double> &lambda, bool ownSolver = false);

} // namespace glossa::solvers
