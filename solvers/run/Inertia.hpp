#pragma once
// A dynamic run's inertia (Time/analysis = dynamic, doc/dynamics.md): the mass and damping
// matrices, the committed velocity, acceleration and forces, and the generalized-alpha terms
// (solvers/stepping/GeneralizedAlpha; or backward Euler, solvers/stepping/BackwardEuler) it adds to
// every residual and tangent of a step's solves through the model evaluator (assembly::InertiaTerm).
// Like the muscle history it has a committed state that only a converged step changes: a failed or
// refused attempt leaves it as it was, and a checkpoint carries it (bit-identical restart).
//
// The residual of a step from t_n to t_{n+1}, divided by (1 - alpha_f):
//   r(u) = f(u) + C v(u) + M [wNew a(u) + wOld a_n] + wF g_n,   g_n = C v_n + f(u_n),
// f the quasi-static residual (f_int - f_ext, Uzawa multipliers included), a(u), v(u) Newmark's
// updates; the tangent K + massFactor M + dampingFactor C. Rayleigh damping C = alpha M + beta K_0,
// K_0 the tangent at the initial state (constant, so C v stays linear in v). The energy-conserving
// step is the trapezoidal rule (rho_inf = 1) with each element's force corrected inside the
// assembly (EnergyConservingForces), from the committed state's element forces and energies.

#include <memory>

#include <nlohmann/json.hpp>

#include "assembly/InertiaTerm.hpp"
#include "solvers/parameters/TimeParameters.hpp"
#include "solvers/run/StepState.hpp"
#include "solvers/stepping/EnergyConservingForces.hpp"
#include "solvers/stepping/GeneralizedAlpha.hpp"

namespace glossa::assembly {
class Assembler;
}

namespace glossa::solvers {

class Inertia : public assembly::InertiaTerm {
public:
  // The state at t = 0: `initial` (displacement and multipliers), the deck's initial velocity
  // (at constrained dofs the support's rate), and the acceleration that balances it,
  // M a_0 = -(C v_0 + f(u_0, 0)) at the free dofs. Collective.
  Inertia(const assembly::Assembler &assembler, const DynamicsParameters &parameters, const StepState &initial);
  ~Inertia() override;

  void beginStep(double dt) override;
  void addTo(const assembly::Vector &u, assembly::Vector *f, assembly::FEMatrix *K) const override;
  const assembly::ElementForceCorrection *elementCorrection() const override { return energyConserving_.get(); }

  // After a converged step to `time`: the velocity, acceleration and forces at `state` become the
  // committed ones. Collective.
  void commit(const StepState &state, double time);

  const assembly::Vector &velocity() const { return *v_; }
  const assembly::Vector &acceleration() const { return *a_; }
  // (1/2) v.M v of the committed state [J]. Collective.
  double kineticEnergy() const;

  // A checkpoint's part: this rank's committed vectors. `committed`: the restored state (its
  // displacement and multipliers), from which the energy-conserving step's element state is
  // computed again rather than stored. Collective.
  void save(nlohmann::json &part) const;
  void restore(const nlohmann::json &part, const StepState &committed);

private:
  // y = C x (zero at constrained dofs' rows is left to the caller).
  void applyDamping(const assembly::Vector &x, assembly::Vector &y) const;
  // g = C v + f(u, time) at the constrained-free rows (zero at constrained ones). Collective.
  void balanceForces(const StepState &state, double time, const assembly::Vector &v, assembly::Vector &g) const;
  // The energy-conserving step's element state at the committed `state`. Collective.
  void recordElements(const StepState &state);
  // a = c0 (u - u_n) - c1 v_n - c2 a_n, and v = v_n + vOld a_n + vNew a.
  void newmark(const assembly::Vector &u, assembly::Vector &a, assembly::Vector &v) const;

  const assembly::Assembler &assembler_;
  DynamicsParameters parameters_;
  GeneralizedAlpha scheme_;
  GeneralizedAlpha::Step step_{};
  Teuchos::RCP<assembly::FEMatrix> mass_, massTangent_, stiffness0_; // M (every entry), M (tangent's), K_0
  std::unique_ptr<assembly::Vector> u_, v_, a_, g_; // committed u_n, v_n, a_n, g_n
  std::unique_ptr<EnergyConservingForces> energyConserving_; // Time/integrator = energy conserving
};

} // namespace glossa::solvers
