#pragma once
// Backward Euler for M a + C v + f(u) = 0 in the step form generalized-alpha's run uses: the
// balance holds at the end of the step,
//   M a_{n+1} + C v_{n+1} + f(u_{n+1}) = 0,  v_{n+1} = (u_{n+1} - u_n)/dt,  a_{n+1} = (v_{n+1} - v_n)/dt,
// so a_{n+1} = (u_{n+1} - u_n - dt v_n)/dt^2 (c0 = 1/dt^2, c1 = 1/dt, c2 = 0) and nothing of the
// last step's acceleration or forces enters. First order, L-stable: a mode of w dt = W keeps per
// step the factor 1/sqrt(1 + W^2) of its amplitude, so a resolved mode loses about pi W of its
// log-amplitude a period (first order in dt) while its period is only lengthened by about W^2/3;
// the unresolved modes of a stiff problem go at once. Plain numbers: no Trilinos.

#include "solvers/stepping/GeneralizedAlpha.hpp"

namespace glossa::solvers {

// The coefficients of one backward Euler step of size dt > 0; std::invalid_argument otherwise.
GeneralizedAlpha::Step backwardEulerStep(double dt);

} // namespace glossa::solvers
