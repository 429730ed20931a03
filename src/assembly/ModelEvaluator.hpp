#pragma once
// Serves the residual and the tangent to NOX through Thyra (Trilinos' model-evaluator
// interface): x is the owned displacement vector, f = f_int - f_ext, W the condensed tangent
// (with element pressures as unknowns, setMixedPressure: the tangent at fixed pressure, whose
// block system solvers/MixedBlockSolver solves).
// The time and the augmented Lagrange multipliers are held fixed during one Newton solve and
// set by the Uzawa loop and the time stepper. The time is also the model's one parameter p_0
// (a vector of length 1, "time"): an evaluation given p_0 is made at that time, which is how
// LOCA's arc-length continuation (solvers/ArcLengthContinuation) moves along the load path.

#include <Thyra_LinearOpWithSolveFactoryBase.hpp>
#include <Thyra_StateFuncModelEvaluatorBase.hpp>

#include "assembly/Assembler.hpp"
#include "assembly/MixedPressureState.hpp"

namespace glossa::assembly {

class ModelEvaluator : public Thyra::StateFuncModelEvaluatorBase<double> {
public:
  ModelEvaluator(Teuchos::RCP<const Assembler> assembler,
                 Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> solverFactory);

  void setTime(double t) {
    time_ = t;
    tangentCached_ = false;
  }
  // The multipliers Lambda per local element; with element pressures as unknowns (setMixedPressure)
  // they are those pressures, updated in place by every accepted Newton iterate.
  void setLambda(std::vector<double> *lambda) {
    lambda_ = lambda;
    tangentCached_ = false;
  }
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
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> timeSpace_; // p_0, locally replicated
  Teuchos::RCP<FEMatrix> matrix_;
  Thyra::ModelEvaluatorBase::InArgs<double> prototypeInArgs_, nominal_;
  Thyra::ModelEvaluatorBase::OutArgs<double> prototypeOutArgs_;
  double time_ = 0.0;
  std::vector<double> *lambda_ = nullptr;
  Teuchos::RCP<MixedPressureState> pressure_;
  const std::vector<double> &lambdaOrZero() const;
  std::vector<fem::MixedBase> bases_;
  mutable std::vector<double> zeroLambda_;
  bool mixed_ = false;
  mutable AssemblyStatus lastStatus_;
  mutable int residualEvaluations_ = 0, tangentEvaluations_ = 0, tangentsFromResidualPass_ = 0;
  // The residual pass also assembles the tangent into matrix_ (most of an element's cost, the
  // point laws, is shared) and remembers where: NOX's next request, the tangent at the accepted
  // iterate, is then served without a second pass. Valid for this x only, and only until the
  // time, the multipliers or the iterates are reset (resetIterates: also where the muscle
  // history or the neural inputs change, before every Newton solve).
  bool tangentIsCachedAt(const Vector &x, double time) const;
  mutable bool tangentCached_ = false;
  mutable Teuchos::RCP<Vector> tangentPoint_;
  mutable std::vector<double> tangentLambda_;
  mutable double tangentTime_ = 0.0;
  mutable AssemblyStatus tangentStatus_;
  mutable double assemblySeconds_ = 0.0;
};

} // namespace glossa::assembly
