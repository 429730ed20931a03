#pragma once
// Serves the problem to NOX, LOCA and the controllers through Thyra (Trilinos' model-evaluator
// interface): x is the owned displacement vector, f = f_int - f_ext, W the condensed tangent
// (with element pressures as unknowns, setMixedPressure: the tangent at fixed pressure, whose
// block system solvers/MixedBlockSolver solves).
//
// Parameters, each with a nominal value that an evaluation uses when it is not given:
//   p0 "time" (length 1): every load's and prescribed motion's time; LOCA's arc-length
//      continuation (solvers/ArcLengthContinuation) moves along the load path through it;
//   p1 "multipliers": the augmented Lagrange multiplier Lambda_e of every element (distributed
//      like the elements), set by the Uzawa loop between Newton solves;
//   p2 "neural inputs" (length: the muscle groups; only with a muscle history): an evaluation at
//      other inputs than the begun step's sees the activations they give over this step.
// Response g0 (with response nodes): the displacements (x, y, z) of the control points, with
// DgDx; DfDp for p2 (the residual's derivative in the inputs). The control points' sensitivity to
// the inputs, dg/dp = -DgDx W^{-1} DfDp, is built from them (solvers/ControlSensitivity).

#include <Thyra_LinearOpWithSolveFactoryBase.hpp>
#include <Thyra_StateFuncModelEvaluatorBase.hpp>

#include "assembly/Assembler.hpp"
#include "assembly/MixedPressureState.hpp"

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

  // Nominal p0.
  void setTime(double t) {
    time_ = t;
    tangentCached_ = false;
  }
  double time() const { return time_; }
  // Nominal p1, per local element (zero until set). With element pressures as unknowns
  // (setMixedPressure) they are those pressures, which every accepted Newton iterate updates:
  // read them back after a solve.
  void setMultipliers(const std::vector<double> &lambda);
  const std::vector<double> &multipliers() const { return lambda_; }
  // Incompressibility/method = mixed: every tangent also linearises the pressure blocks, trial
  // evaluations see the block solver's pending pressure increment, and accepted iterates commit it.
  void setMixedPressure(Teuchos::RCP<MixedPressureState> state) { pressure_ = std::move(state); }
  Teuchos::RCP<MixedPressureState> mixedPressure() const { return pressure_; }
  // Three-field Newton iterates (Q1-P0): reset to the exact condensation at u before a solve,
  // advanced to every accepted Newton iterate (fem::MixedBase).
  void resetIterates(const Vector &u);
  void advanceIterates(const Vector &u);
  // Status of the last evaluation: false if an element inverted (f was set to NaN so that
  // NOX's finite-value test stops the solve).
  const AssemblyStatus &lastStatus() const { return lastStatus_; }
  Teuchos::RCP<FEMatrix> matrix() const { return matrix_; }
  int residualEvaluations() const { return residualEvaluations_; }
  int tangentEvaluations() const { return tangentEvaluations_; }
  // Tangents NOX asked for that the residual pass at the same point had already assembled.
  int tangentsFromResidualPass() const { return tangentsFromResidualPass_; }
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
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> solverFactory_;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> space_;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> timeSpace_;     // p0, locally replicated
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> elementSpace_;  // p1, one entry per element
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> inputSpace_;    // p2, locally replicated
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> responseSpace_; // g0, locally replicated
  model::MuscleHistory *history_ = nullptr;
  std::vector<mesh::NodeId> responseNodes_;
  int groups_ = 0;
  Teuchos::RCP<FEMatrix> matrix_;
  Thyra::ModelEvaluatorBase::InArgs<double> prototypeInArgs_, nominal_;
  Thyra::ModelEvaluatorBase::OutArgs<double> prototypeOutArgs_;
  double time_ = 0.0;
  mutable std::vector<double> lambda_; // nominal p1; mixed: the pressures, committed by evaluations
  Teuchos::RCP<MixedPressureState> pressure_;
  std::vector<fem::MixedBase> bases_;
  // The responses and derivatives an evaluation asked for, at its x, time and multipliers.
  void evaluateResponse(const Vector &x, const Thyra::ModelEvaluatorBase::OutArgs<double> &out) const;
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
};

} // namespace glossa::assembly
