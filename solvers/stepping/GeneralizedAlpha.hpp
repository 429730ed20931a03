#pragma once
// Generalized-alpha (Chung & Hulbert, J. Appl. Mech. 60, 1993) for M a + C v + f(u) = 0,
// f = f_int - f_ext, with the spectral radius rho_inf at infinite frequency as its one parameter
// (eq. 25 and 17 of the paper):
//   alpha_m = (2 rho_inf - 1)/(rho_inf + 1),  alpha_f = rho_inf/(rho_inf + 1),
//   gamma = 1/2 - alpha_m + alpha_f,           beta = (1 - alpha_m + alpha_f)^2 / 4,
// so rho_inf = 1 is Newmark's trapezoidal rule (alpha_m = alpha_f = 1/2, gamma = 1/2, beta = 1/4).
// The balance holds at the generalized midpoint, the forces taken in the generalized trapezoidal
// form (the same scheme for a linear f):
//   M [(1 - am) a_{n+1} + am a_n] + (1 - af)[C v_{n+1} + f(u_{n+1})] + af [C v_n + f(u_n)] = 0,
// with Newmark's updates
//   a_{n+1} = c0 (u_{n+1} - u_n) - c1 v_n - c2 a_n,   v_{n+1} = v_n + vOld a_n + vNew a_{n+1}.
// Divided by (1 - af), the balance is the quasi-static residual f(u_{n+1}) plus inertia, damping
// and the last step's forces; its tangent K + massFactor M + dampingFactor C. Plain numbers: no
// Trilinos, unit-tested on a single oscillator.

namespace glossa::solvers {

class GeneralizedAlpha {
public:
  // rho_inf in [0, 1]; std::invalid_argument otherwise.
  explicit GeneralizedAlpha(double spectralRadius);

  double alphaM() const { return alphaM_; }
  double alphaF() const { return alphaF_; }
  double gamma() const { return gamma_; }
  double beta() const { return beta_; }

  // The coefficients of one step of size dt > 0.
  struct Step {
    double dt;
    double c0, c1, c2;    // a_{n+1} = c0 (u_{n+1} - u_n) - c1 v_n - c2 a_n
    double vOld, vNew;    // v_{n+1} = v_n + vOld a_n + vNew a_{n+1}
    double newAcceleration, oldAcceleration; // M's weights on a_{n+1}, a_n: (1-am)/(1-af), am/(1-af)
    double oldForces;     // the weight of C v_n + f(u_n): af/(1-af)
    double massFactor;    // d/du of the inertia: (1-am)/(1-af) c0 (times M)
    double dampingFactor; // d/du of C v_{n+1}: vNew c0 = gamma/(beta dt) (times C)
  };
  Step step(double dt) const;

private:
  double alphaM_, alphaF_, gamma_, beta_;
};

} // namespace glossa::solvers
