#pragma once
// The discrete gradient that makes a step conserve an element's stored energy exactly
// (O. Gonzalez, J. Nonlinear Sci. 6, 1996: "time integration and discrete Hamiltonian systems";
// doc/dynamics.md, "The energy-conserving step"). The trapezoidal rule takes an element's force
// over a step as the mean f_mean = (f(u_n) + f(u_{n+1}))/2, whose work f_mean . du differs from
// the stored energy's change dW = W(u_{n+1}) - W(u_n) by the quadrature error of a nonlinear
// force, O(|du|^3). Adding
//   c d,   d = du minus its mean nodal translation,   c = (dW - f_mean . du) / (d . du)
// makes the work equal dW (d . du = |d|^2) while the correction vanishes with du at second
// order (the scheme stays second order and consistent), sums to zero over the nodes (linear
// momentum is kept) and vanishes for a rigid translation (which neither stores energy nor
// works against the element's balanced forces). Plain Eigen: no Trilinos, unit-tested alone.

#include "fem/Q1P0Element.hpp"

namespace glossa::fem {

struct DiscreteGradientCorrection {
  ElementVector force = ElementVector::Zero(); // c d [N]
  double coefficient = 0.0;                    // c [N/m]; its tangent is c P, P d = d
};

// du: the element's nodal displacement change over the step; W0, W1 its stored energy at the
// step's ends; meanForce: the force the step already uses, (f(u_n) + f(u_{n+1}))/2. A change of
// the energy below its round-off (or a pure translation) gives no correction.
DiscreteGradientCorrection discreteGradientCorrection(const ElementVector &du, double W0, double W1,
                                                      const ElementVector &meanForce);

// K += c P with P = I - (1/8) (1 1^T) per component: the derivative of c d with respect to
// u_{n+1} at fixed c (the derivative of c itself, of the order of the correction, is left out).
void addTranslationFreeIdentity(ElementMatrix &K, double c);

} // namespace glossa::fem
