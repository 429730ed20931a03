#pragma once
// Serves the problem to NOX, LOCA and the controllers through Thyra (Trilinos' model-evaluator
// interface): x is the owned displacement vector, f = f_int - f_ext, W the condensed tangent.
// With element pressures as unknowns (setMixedPressure, Incompressibility/method = mixed) x is
// the product [u; p~] of the displacements and the scaled element pressures p~_e = p_e / sigma_e
// (MixedPressureState), f = [f_int - f_ext; sigma_e (v_e - V_e theta_phys(p_e))] and W the 2 x 2
// blocked tangent [K, (sigma B)^T; sigma B, -C~], which solvers/linear/MixedBlockSolver solves.
//
// Parameters, each with a nominal value that an evaluation uses when it is not given:
//   p0 "time" (length 1): every load's and prescribed motion's time; LOCA's arc-length
//      continuation (solvers/stepping/ArcLengthContinuation) moves along the load path through it;
//   p1 "multipliers": the augmented Lagrange multiplier Lambda_e of every element (distributed
//      like the elements), set by the Uzawa loop between Newton solves;
//   p2 "neural inputs" (length: the muscle groups; only with a muscle history): an evaluation at
//      other inputs than the begun step's sees the activations they give over this step.
// Response g0 (with response nodes): the displacements (x, y, z) of the control points, with
// DgDx; DfDp for p2 (the residual's derivative in the inputs). The control points' sensitivity to
// the inputs, dg/dp = -DgDx W^{-1} DfDp, is built from them (solvers/control/ControlSensitivity).

#include <Thyra_LinearOpWithSolveFactoryBase.hpp>
#include <Thyra_StateFuncModelEvaluatorBase.hpp>
#include <functional>

#include "assembly/Assembler.hpp"
#include "assembly/InertiaTerm.hpp"
#include "assembly/MixedPressureState.hpp"
#include "assembly/ResultEvaluator.hpp"

namespace glossa::assembly {

class ModelEvaluator : public Thyra::StateFuncModelEvaluatorBase<double> {
public:
  enum Parameter { kTime = 0, kMultipliers = 1, kNeuralInputs = 2 };

  // `history`: the muscle state the assembler reads, which evaluations at other neural inputs
  // change for their duration (null: no p2). `responseNodes`: the mesh nodes whose displacements
  // are the response g0 (empty: no response).
  ModelEvaluator(Teuchos::RCP<const Assembler> assembler,
                 Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> solverFactory,
                 model::MuscleHistory *history = nullptr, std::vector<mesh::NodeId> responseNodes = {});

  // Nominal p0, and the pose of every moving obstacle (which the contacts' output and Uzawa
  // updates at a converged state read).
  void setTime(double t);
  // Nominal p0 and p2 for a step of length dt from the committed state: the time, and the neural
  // inputs of every muscle group over the step (a controller's candidate; empty: the deck's
  // u(t)). The muscle history begins the step at them (its trial activation, eq. 24), which every
  // evaluation at the nominal p2 reads. Needs the history (the constructor's) when inputs are given.
  void beginStep(double time, double dt, const std::vector<double> &inputs = {});
  // A dynamic run's inertia (owned by the caller, outliving this model): every residual and
  // tangent then carries it, and beginStep begins its step. Null: quasi-static.
  void setInertia(InertiaTerm *inertia) {
    inertia_ = inertia;
    tangentCached_ = false;
  }
  // Nominal p1, per local element (zero until set). With element pressures as unknowns
  // (setMixedPressure) they are those pressures, which every accepted Newton iterate updates:
  // read them back after a solve.
  void setMultipliers(const std::vector<double> &lambda);
  const std::vector<double> &multipliers() const { return lambda_; }
  // Incompressibility/method = mixed, before the first evaluation: x becomes [u; p~] (above);
  // every evaluation linearises the pressure blocks into `state`, which the block solver reads.
  void setMixedPressure(Teuchos::RCP<MixedPressureState> state);
  Teuchos::RCP<MixedPressureState> mixedPressure() const { return pressure_; }
  // x for displacements u and the nominal multipliers (mixed: the pressures); the displacement
  // part of an x; and u (and, mixed, the nominal pressures) from a solution x.
  Teuchos::RCP<Thyra::VectorBase<double>> initialGuess(const Vector &u) const;
  Teuchos::RCP<const Vector> displacementOf(const Thyra::VectorBase<double> &x) const;
  void acceptSolution(const Thyra::VectorBase<double> &x, Vector &u);
  // Three-field Newton iterates (Q1-P0): reset to the exact condensation at u before a solve,
  // advanced to every accepted Newton iterate (fem::MixedBase).
  void resetIterates(const Vector &u);
  void advanceIterates(const Vector &u);
  // While a Newton solve runs, whether its update test would pass for the update from the last
  // accepted iterate to x (NewtonSolver sets it to mirror its test; empty: no forecast). A
  // residual request at such an x skips the tangent the residual pass otherwise assembles
  // with it for NOX's next request: the solve is about to stop, and that tangent was unused in
  // every final pass (200 of the 493 passes of the §7.1 (a) scene). Should the residual test
  // still fail there, NOX's tangent request costs one full pass.
  using ConvergenceForecast = std::function<bool(const Vector &update, const Vector &x)>;
  void setConvergenceForecast(ConvergenceForecast forecast) { forecast_ = std::move(forecast); }
  // Residual requests answered without the tangent because of the forecast.
  int residualOnlyPasses() const { return residualOnlyPasses_; }
  // Status of the last evaluation: false if an element inverted (f was set to NaN so that
  // NOX's finite-value test stops the solve).
  const AssemblyStatus &lastStatus() const { return lastStatus_; }
  Teuchos::RCP<FEMatrix> matrix() const { return matrix_; }
  int residualEvaluations() const { return residualEvaluations_; }
  int tangentEvaluations() const { return tangentEvaluations_; }
  // Tangents NOX asked for that the residual pass at the same point had already assembled.
  int tangentsFromResidualPass() const { return tangentsFromResidualPass_; }
  // Element evaluations of this rank's elements: those that finished from a kept displacement
  // part (assembly/ElementPartCache) and those evaluated.
  ElementPartCounts elementPartCounts() const { return assembler_->elementPartCounts(); }
  double assemblySeconds() const { return assemblySeconds_; }

  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_x_space() const override { return space_; }
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_f_space() const override { return space_; }
  Thyra::ModelEvaluatorBase::InArgs<double> getNominalValues() const override;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_p_space(int l) const override;
  Teuchos::RCP<const Teuchos::Array<std::string>> get_p_names(int l) const override;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_g_space(int j) const override;
  Thyra::ModelEvaluatorBase::InArgs<double> createInArgs() const override { return prototypeInArgs_; }
  Teuchos::RCP<Thyra::LinearOpBase<double>> create_W_op() const override;
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> get_W_factory() const override {
    return solverFactory_;
  }

private:
  Thyra::ModelEvaluatorBase::OutArgs<double> createOutArgsImpl() const override { return prototypeOutArgs_; }
  void evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<double> &in,
                     const Thyra::ModelEvaluatorBase::OutArgs<double> &out) const override;

  Teuchos::RCP<const Assembler> assembler_;
  ResultEvaluator results_; // of assembler_: the response g0 gathers the displacements
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> solverFactory_;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> space_;         // x and f: u, or [u; p~]
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> uSpace_;        // the owned displacements
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> timeSpace_;     // p0, locally replicated
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> elementSpace_;  // p1, one entry per element
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> inputSpace_;    // p2, locally replicated
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> responseSpace_; // g0, locally replicated
  model::MuscleHistory *history_ = nullptr;
  InertiaTerm *inertia_ = nullptr;
  const ElementForceCorrection *elementCorrection() const { return inertia_ ? inertia_->elementCorrection() : nullptr; }
  std::vector<mesh::NodeId> responseNodes_;
  int groups_ = 0;
  Teuchos::RCP<FEMatrix> matrix_;
  Thyra::ModelEvaluatorBase::InArgs<double> prototypeInArgs_, nominal_;
  Thyra::ModelEvaluatorBase::OutArgs<double> prototypeOutArgs_;
  double time_ = 0.0;
  std::vector<double> lambda_; // nominal p1; mixed: the pressures of the last accepted solution
  Teuchos::RCP<MixedPressureState> pressure_;
  std::vector<fem::MixedBase> bases_;
  // An evaluation of the mixed problem at x = [u; p~].
  void evaluateMixed(const Thyra::ModelEvaluatorBase::InArgs<double> &in,
                     const Thyra::ModelEvaluatorBase::OutArgs<double> &out, double time) const;
  // The responses and derivatives an evaluation asked for, at its x, time and multipliers.
  void evaluateResponse(const Vector &x, const Thyra::ModelEvaluatorBase::OutArgs<double> &out) const;
  // Per local element: whether it has a fibre family of muscle group `group`.
  std::vector<char> groupElements(int group) const;
  void evaluateInputDerivative(const Vector &x, double time, const std::vector<double> &lambda,
                               const Thyra::VectorBase<double> *inputs, Thyra::MultiVectorBase<double> &dfdp) const;
  bool mixed_ = false;
  mutable AssemblyStatus lastStatus_;
  mutable int residualEvaluations_ = 0, tangentEvaluations_ = 0, tangentsFromResidualPass_ = 0;
  // The residual pass also assembles the tangent into matrix_ (most of an element's cost, the
  // point laws, is shared) and remembers where: NOX's next request, the tangent at the accepted
  // iterate, is then served without a second pass. Valid for this x only, and only until the
  // time, the multipliers or the iterates are reset (resetIterates: also where the muscle
  // history or the neural inputs change, before every Newton solve).
  bool tangentIsCachedAt(const Vector &x, double time, const std::vector<double> &lambda) const;
  mutable bool tangentCached_ = false;
  mutable Teuchos::RCP<Vector> tangentPoint_;
  mutable std::vector<double> tangentLambda_;
  mutable double tangentTime_ = 0.0;
  mutable AssemblyStatus tangentStatus_;
  mutable double assemblySeconds_ = 0.0;
  ConvergenceForecast forecast_;
  Teuchos::RCP<Vector> accepted_; // the last accepted Newton iterate (resetIterates, advanceIterates)
  mutable Teuchos::RCP<Vector> update_;
  mutable int residualOnlyPasses_ = 0;
  bool updateForecastsConvergence(const Vector &x) const;
};

} // namespace glossa::assembly
