#include "solvers/linear/MixedBlockSolver.hpp"

#include <Teko_BlockUpperTriInverseOp.hpp>
#include <Teko_Utilities.hpp>
#include <Thyra_PhysicallyBlockedLinearOpBase.hpp>
#include <Thyra_DefaultDiagonalLinearOp.hpp>
#include <Thyra_DefaultIdentityLinearOp.hpp>
#include <Thyra_DefaultLinearOpSource.hpp>
#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_DefaultScaledAdjointLinearOp.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_MultiVectorStdOps.hpp>
#include <Thyra_PreconditionerFactoryBase.hpp>
#include <Thyra_ProductMultiVectorBase.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

namespace glossa::solvers {

namespace {

using Teuchos::RCP;
using Teuchos::rcp;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, assembly::LO, assembly::GO, assembly::Node>;

Teuchos::RCP<const Thyra::LinearOpBase<double>> diagonalOp(const RCP<const Thyra::VectorSpaceBase<double>> &space,
                                                           const assembly::Vector &d, double scale) {
  auto v = rcp(new assembly::Vector(d, Teuchos::Copy));
  v->scale(scale);
  return Thyra::diagonal<double>(Thyra::createVector(RCP<assembly::Vector>(v), space));
}

// The solve object NOX holds for the blocked tangent A = [K, B^T; B, -C] of the model evaluator.
class MixedBlockSolve : public Thyra::LinearOpWithSolveBase<double> {
public:
  MixedBlockSolve(RCP<assembly::MixedPressureState> state, RCP<Thyra::PreconditionerFactoryBase<double>> precFactory,
                  RCP<Thyra::LinearOpWithSolveFactoryBase<double>> krylov)
      : state_(std::move(state)), precFactory_(std::move(precFactory)), krylov_(std::move(krylov)) {}

  void initialize(const RCP<const Thyra::LinearOpSourceBase<double>> &source) {
    source_ = source;
    A_ = Teuchos::rcp_dynamic_cast<const Thyra::PhysicallyBlockedLinearOpBase<double>>(source->getOp(), true);
    const auto K = A_->getBlock(0, 0);
    // K_hat^{-1}: one preconditioner object for the life of this solve object, so that MueLu's
    // "reuse: type" applies from one tangent to the next.
    if (!precFactory_.is_null()) {
      if (prec_.is_null()) prec_ = precFactory_->createPrec();
      precFactory_->initializePrec(Thyra::defaultLinearOpSource<double>(K), prec_.get());
    }
    blockSolve_.reset();
  }
  RCP<const Thyra::LinearOpSourceBase<double>> source() const { return source_; }

  RCP<const Thyra::VectorSpaceBase<double>> range() const override { return A_.is_null() ? Teuchos::null : A_->range(); }
  RCP<const Thyra::VectorSpaceBase<double>> domain() const override {
    return A_.is_null() ? Teuchos::null : A_->domain();
  }

protected:
  bool opSupportedImpl(Thyra::EOpTransp t) const override { return t == Thyra::NOTRANS; }
  void applyImpl(const Thyra::EOpTransp t, const Thyra::MultiVectorBase<double> &X,
                 const Teuchos::Ptr<Thyra::MultiVectorBase<double>> &Y, const double alpha, const double beta) const override {
    A_->apply(t, X, Y, alpha, beta);
  }
  bool solveSupportsImpl(Thyra::EOpTransp t) const override { return t == Thyra::NOTRANS; }
  bool solveSupportsSolveMeasureTypeImpl(Thyra::EOpTransp t, const Thyra::SolveMeasureType &) const override {
    return t == Thyra::NOTRANS;
  }

  Thyra::SolveStatus<double> solveImpl(const Thyra::EOpTransp, const Thyra::MultiVectorBase<double> &B,
                                       const Teuchos::Ptr<Thyra::MultiVectorBase<double>> &X,
                                       const Teuchos::Ptr<const Thyra::SolveCriteria<double>> criteria) const override {
    if (blockSolve_.is_null()) buildBlockSolve();
    Thyra::SolveStatus<double> status = blockSolve_->solve(Thyra::NOTRANS, B, X, criteria);
    // NOX counts Krylov iterations from these (Stratimikos' Belos adapter sets both names).
    if (status.extraParameters.is_null()) status.extraParameters = Teuchos::parameterList();
    return status;
  }

private:
  void buildBlockSolve() const {
    const assembly::MixedPressureState &s = *state_;
    TEUCHOS_TEST_FOR_EXCEPTION(s.schurDiagonal.is_null(), std::logic_error,
                               "mixed block solve before the pressure blocks were linearised");
    const auto uSpace = A_->getBlock(0, 0)->range();
    const auto pressureSpace = A_->getBlock(1, 0)->range();
    // P^{-1} = [K_hat B^T; 0 -S_hat]^{-1}, S_hat = C + M_p / mu (diagonal, inverted exactly).
    auto inverseSchur = rcp(new assembly::Vector(*s.schurDiagonal, Teuchos::Copy));
    inverseSchur->reciprocal(*s.schurDiagonal);
    const Teko::LinearOp invK = prec_.is_null() ? Thyra::identity<double>(uSpace) : prec_->getUnspecifiedPrecOp();
    const Teko::LinearOp invS = diagonalOp(pressureSpace, *inverseSchur, -1.0);
    Teko::BlockedLinearOp A = Teuchos::rcp_const_cast<Thyra::PhysicallyBlockedLinearOpBase<double>>(A_);
    const Teko::LinearOp P = Teko::createBlockUpperTriInverseOp(A, {invK, invS}, "mixed Q1-P0 block preconditioner");
    blockSolve_ = krylov_->createOp();
    Thyra::initializePreconditionedOp<double>(*krylov_, Teko::LinearOp(A_), Thyra::unspecifiedPrec<double>(P),
                                              blockSolve_.ptr());
  }

  RCP<assembly::MixedPressureState> state_;
  RCP<Thyra::PreconditionerFactoryBase<double>> precFactory_;
  RCP<Thyra::LinearOpWithSolveFactoryBase<double>> krylov_;
  RCP<const Thyra::LinearOpSourceBase<double>> source_;
  RCP<const Thyra::PhysicallyBlockedLinearOpBase<double>> A_;
  RCP<Thyra::PreconditionerBase<double>> prec_;
  mutable RCP<Thyra::LinearOpWithSolveBase<double>> blockSolve_;
};

class MixedBlockSolveFactory : public Thyra::LinearOpWithSolveFactoryBase<double> {
public:
  MixedBlockSolveFactory(RCP<assembly::MixedPressureState> state, RCP<Thyra::PreconditionerFactoryBase<double>> prec,
                         RCP<Thyra::LinearOpWithSolveFactoryBase<double>> krylov)
      : state_(std::move(state)), prec_(std::move(prec)), krylov_(std::move(krylov)) {}

  bool isCompatible(const Thyra::LinearOpSourceBase<double> &source) const override {
    return !source.getOp().is_null();
  }
  RCP<Thyra::LinearOpWithSolveBase<double>> createOp() const override {
    return rcp(new MixedBlockSolve(state_, prec_, krylov_));
  }
  void initializeOp(const RCP<const Thyra::LinearOpSourceBase<double>> &source, Thyra::LinearOpWithSolveBase<double> *op,
                    const Thyra::ESupportSolveUse) const override {
    auto *solve = dynamic_cast<MixedBlockSolve *>(op);
    TEUCHOS_TEST_FOR_EXCEPTION(solve == nullptr, std::logic_error, "not a mixed block solve object");
    solve->initialize(source);
  }
  void uninitializeOp(Thyra::LinearOpWithSolveBase<double> *op, RCP<const Thyra::LinearOpSourceBase<double>> *source,
                      RCP<const Thyra::PreconditionerBase<double>> *prec,
                      RCP<const Thyra::LinearOpSourceBase<double>> *approx, Thyra::ESupportSolveUse *use) const override {
    auto *solve = dynamic_cast<MixedBlockSolve *>(op);
    if (source && solve) *source = solve->source();
    if (prec) *prec = Teuchos::null;
    if (approx) *approx = Teuchos::null;
    if (use) *use = Thyra::SUPPORT_SOLVE_UNSPECIFIED;
  }
  void setParameterList(const RCP<Teuchos::ParameterList> &list) override { list_ = list; }
  RCP<Teuchos::ParameterList> getNonconstParameterList() override { return list_; }
  RCP<Teuchos::ParameterList> unsetParameterList() override {
    auto l = list_;
    list_ = Teuchos::null;
    return l;
  }

private:
  RCP<assembly::MixedPressureState> state_;
  RCP<Thyra::PreconditionerFactoryBase<double>> prec_;
  RCP<Thyra::LinearOpWithSolveFactoryBase<double>> krylov_;
  RCP<Teuchos::ParameterList> list_;
};

} // namespace

RCP<Thyra::LinearOpWithSolveFactoryBase<double>>
buildMixedBlockSolver(const LinearSolverParameters &linearSection, const LinearSolverContext &context,
                      RCP<assembly::MixedPressureState> state) {
  const bool none = linearSection.preconditioner == Preconditioner::none;
  return rcp(new MixedBlockSolveFactory(std::move(state),
                                        none ? Teuchos::null : buildDisplacementPreconditioner(linearSection, context),
                                        buildBlockKrylovSolver(linearSection)));
}

} // namespace glossa::solvers
