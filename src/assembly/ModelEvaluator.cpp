#include "assembly/ModelEvaluator.hpp"

#include <chrono>
#include <limits>

#include <Teuchos_CommHelpers.hpp>
#include <Thyra_DefaultSpmdVectorSpace.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

namespace glossa::assembly {

using Extract = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>;
using MEB = Thyra::ModelEvaluatorBase;

ModelEvaluator::ModelEvaluator(Teuchos::RCP<const Assembler> assembler,
                               Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> solverFactory)
    : assembler_(std::move(assembler)), solverFactory_(std::move(solverFactory)) {
  space_ = Thyra::createVectorSpace<double, LO, GO, Node>(assembler_->ownedMap());
  matrix_ = assembler_->createMatrix();

  MEB::InArgsSetup<double> in;
  in.setModelEvalDescription("Glossa Q1-P0 residual");
  in.setSupports(MEB::IN_ARG_x);
  in.set_Np(1);
  prototypeInArgs_ = in;
  timeSpace_ = Thyra::locallyReplicatedDefaultSpmdVectorSpace<double>(
      Thyra::convertTpetraToThyraComm(assembler_->ownedMap()->getComm()), 1);
  nominal_ = in;

  auto x0 = Thyra::createMember(space_);
  Thyra::V_S(x0.ptr(), 0.0);
  nominal_.set_x(x0);

  MEB::OutArgsSetup<double> out;
  out.setModelEvalDescription("Glossa Q1-P0 residual");
  out.set_Np_Ng(1, 0);
  out.setSupports(MEB::OUT_ARG_f);
  out.setSupports(MEB::OUT_ARG_W_op);
  prototypeOutArgs_ = out;
}

MEB::InArgs<double> ModelEvaluator::getNominalValues() const {
  MEB::InArgs<double> nominal = nominal_;
  auto p = Thyra::createMember(timeSpace_);
  Thyra::set_ele(0, time_, p.ptr());
  nominal.set_p(0, p);
  return nominal;
}

Teuchos::RCP<const Thyra::VectorSpaceBase<double>> ModelEvaluator::get_p_space(int l) const {
  TEUCHOS_TEST_FOR_EXCEPTION(l != 0, std::out_of_range, "the model has one parameter, the time");
  return timeSpace_;
}

Teuchos::RCP<const Teuchos::Array<std::string>> ModelEvaluator::get_p_names(int l) const {
  TEUCHOS_TEST_FOR_EXCEPTION(l != 0, std::out_of_range, "the model has one parameter, the time");
  return Teuchos::rcp(new Teuchos::Array<std::string>(1, "time"));
}

const std::vector<double> &ModelEvaluator::lambdaOrZero() const {
  if (lambda_) return *lambda_;
  zeroLambda_.assign(assembler_->numLocalElements(), 0.0);
  return zeroLambda_;
}

void ModelEvaluator::resetIterates(const Vector &u) {
  tangentCached_ = false;
  // With pressures as unknowns the kernel's volumetric energy is zero and the element pressure is
  // the multiplier itself: the three-field iterates would carry nothing.
  mixed_ = assembler_->scene().formulation == model::ElementFormulation::Q1P0 && pressure_.is_null();
  if (!pressure_.is_null()) pressure_->pending = false;
  if (mixed_) bases_ = assembler_->mixedBases(u, lambdaOrZero(), nullptr);
}

void ModelEvaluator::advanceIterates(const Vector &u) {
  if (!pressure_.is_null() && lambda_) pressure_->commit(*lambda_);
  if (mixed_) bases_ = assembler_->mixedBases(u, lambdaOrZero(), &bases_);
}

Teuchos::RCP<Thyra::LinearOpBase<double>> ModelEvaluator::create_W_op() const {
  // One matrix serves every W: NOX asks for it once per group.
  return Thyra::tpetraLinearOp<double, LO, GO, Node>(space_, space_, matrix_);
}

void ModelEvaluator::evalModelImpl(const MEB::InArgs<double> &in, const MEB::OutArgs<double> &out) const {
  const auto start = std::chrono::steady_clock::now();
  const Teuchos::RCP<const Vector> x = Extract::getConstTpetraVector(in.get_x());
  const Teuchos::RCP<Thyra::VectorBase<double>> fThyra = out.get_f();
  const Teuchos::RCP<Thyra::LinearOpBase<double>> W = out.get_W_op();
  Teuchos::RCP<Vector> f = fThyra.is_null() ? Teuchos::null : Extract::getTpetraVector(fThyra);
  const Teuchos::RCP<const Thyra::VectorBase<double>> p = in.get_p(0);
  const double time = p.is_null() ? time_ : Thyra::get_ele(*p, 0);
  FEMatrix *K = nullptr;
  if (!W.is_null()) {
    auto op = Extract::getTpetraOperator(W);
    K = dynamic_cast<FEMatrix *>(op.get());
    TEUCHOS_TEST_FOR_EXCEPTION(K == nullptr, std::logic_error, "W_op is not the model's FECrsMatrix");
  }
  if (K && !pressure_.is_null()) {
    TEUCHOS_TEST_FOR_EXCEPTION(lambda_ == nullptr, std::logic_error, "mixed pressure unknowns need the multipliers");
    // A tangent at a trial point: the point is the iterate, so its pressure is too.
    pressure_->commit(*lambda_);
    pressure_->linearise(*assembler_, *x, *lambda_);
  }
  const std::vector<double> &lambda = pressure_.is_null() ? lambdaOrZero() : pressure_->trialPressure(lambdaOrZero());
  if (K == matrix_.get() && f.is_null() && tangentIsCachedAt(*x, time)) {
    // The tangent of the accepted iterate, assembled with its residual. The trial point's
    // Newton update from the previous bases is the accepted iterate's own state
    // (advanceIterates), so the matrix is the one a fresh pass would assemble.
    tangentCached_ = false;
    lastStatus_ = tangentStatus_;
    ++tangentsFromResidualPass_;
    assemblySeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return;
  }
  // With pressures as unknowns a tangent also linearises the pressure blocks: no shared pass.
  const bool withTangent = !f.is_null() && !K && pressure_.is_null();
  Vector fScratch(assembler_->ownedMap());
  if (withTangent) {
    lastStatus_ = assembler_->assemble(*x, time, lambda, mixed_ ? &bases_ : nullptr, f.get(), matrix_.get(),
                                       /*trialPoint=*/true);
    tangentCached_ = lastStatus_.valid;
    if (tangentCached_) {
      if (tangentPoint_.is_null() || !tangentPoint_->getMap()->isSameAs(*x->getMap()))
        tangentPoint_ = Teuchos::rcp(new Vector(x->getMap()));
      tangentPoint_->assign(*x);
      tangentLambda_ = lambda;
      tangentTime_ = time;
      tangentStatus_ = lastStatus_;
    }
  } else {
    tangentCached_ = false;
    lastStatus_ = assembler_->assemble(*x, time, lambda, mixed_ ? &bases_ : nullptr,
                                       f.is_null() ? (K ? &fScratch : nullptr) : f.get(), K);
  }
  if (!lastStatus_.valid && !f.is_null()) f->putScalar(std::numeric_limits<double>::quiet_NaN());
  if (!f.is_null()) ++residualEvaluations_;
  if (K || withTangent) ++tangentEvaluations_;
  assemblySeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool ModelEvaluator::tangentIsCachedAt(const Vector &x, double time) const {
  int same = tangentCached_ && tangentTime_ == time && tangentLambda_ == lambdaOrZero() ? 1 : 0;
  if (same) {
    auto a = x.getData(0), b = tangentPoint_->getData(0);
    for (std::size_t i = 0; i < x.getLocalLength() && same; ++i) same = a[i] == b[i] ? 1 : 0;
  }
  int all = 0;
  Teuchos::reduceAll(*x.getMap()->getComm(), Teuchos::REDUCE_MIN, same, Teuchos::outArg(all));
  return all == 1;
}

} // namespace glossa::assembly
