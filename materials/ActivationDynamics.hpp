#pragma once
// Muscle activation dynamics (paper eq. 24, Pandy et al. 1990):
//   d alpha/dt = (1/tau_R) (1 - alpha) u + (1/tau_F) (alpha_min - alpha) (1 - u),
// u the neural input, in {0, 1} in the paper, any value in [0, 1] accepted (a relaxation).
// The paper's values: tau_R = tau_F = 150 ms (genioglossus EMG), alpha_min = 0.
// Backward Euler is linear in alpha_n, so each step has a closed form:
//   alpha_n = (alpha_{n-1} + dt (u/tau_R + alpha_min (1-u)/tau_F)) / (1 + dt (u/tau_R + (1-u)/tau_F)),
// i.e. (alpha_{n-1} tau_R + dt)/(tau_R + dt) for u = 1 and (alpha_{n-1} tau_F + dt alpha_min)/(tau_F + dt)
// for u = 0. The fraction of the full muscle response is FFMR = T0s alpha (§6).

namespace glossa::materials {

struct ActivationParameters {
  double tauR = 0.150;    // rise time constant [s], > 0
  double tauF = 0.150;    // fall time constant [s], > 0
  double alphaMin = 0.0;  // minimum activation, in [0, 1)
};

class ActivationDynamics {
 public:
  explicit ActivationDynamics(ActivationParameters parameters = {});  // throws on invalid values

  // One backward-Euler step from alphaOld (in [alphaMin, 1]) with input u in [0, 1] over dt > 0.
  // Throws std::invalid_argument otherwise.
  double step(double alphaOld, double u, double dt) const;
  // d step / d u at the same arguments (the controller's sensitivity of alpha to the input).
  double stepInputDerivative(double alphaOld, double u, double dt) const;
  // The exact solution after time t >= 0 with constant u: alpha_inf + (alpha0 - alpha_inf) e^{-k t},
  // k = u/tau_R + (1-u)/tau_F, alpha_inf = (u/tau_R + alpha_min (1-u)/tau_F) / k.
  double exact(double alpha0, double u, double t) const;

  const ActivationParameters &parameters() const { return p_; }

 private:
  ActivationParameters p_;
};

// FFMR = T0s alpha (paper §6), T0s in [0, 1].
inline double fractionOfFullMuscleResponse(double T0s, double alpha) { return T0s * alpha; }

}  // namespace glossa::materials
