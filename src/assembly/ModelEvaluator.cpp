#include "assembly/ModelEvaluator.hpp"

#include <algorithm>
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
                               Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> solverFactory,
                               model::MuscleHistory *history, std::vector<mesh::NodeId> responseNodes)
    : assembler_(std::move(assembler)), solverFactory_(std::move(solverFactory)), history_(history),
      responseNodes_(std::move(responseNodes)) {
  space_ = Thyra::createVectorSpace<double, LO, GO, Node>(assembler_->ownedMap());
  matrix_ = assembler_->createMatrix();
  lambda_.assign(assembler_->numLocalElements(), 0.0);
  const auto comm = Thyra::convertTpetraToThyraComm(assembler_->ownedMap()->getComm());
  timeSpace_ = Thyra::locallyReplicatedDefaultSpmdVectorSpace<double>(comm, 1);
  elementSpace_ = Thyra::createVectorSpace<double, LO, GO, Node>(assembler_->elementMap());
  groups_ = history_ ? static_cast<int>(assembler_->scene().muscles.groups.size()) : 0;
  if (groups_ > 0) inputSpace_ = Thyra::locallyReplicatedDefaultSpmdVectorSpace<double>(comm, groups_);
  const int Ng = responseNodes_.empty() ? 0 : 1;
  if (Ng > 0)
    responseSpace_ =
        Thyra::locallyReplicatedDefaultSpmdVectorSpace<double>(comm, 3 * static_cast<int>(responseNodes_.size()));
  const int Np = groups_ > 0 ? 3 : 2;

  MEB::InArgsSetup<double> in;
  in.setModelEvalDescription("Glossa Q1-P0 residual");
  in.setSupports(MEB::IN_ARG_x);
  in.set_Np(Np);
  prototypeInArgs_ = in;
  nominal_ = in;
  auto x0 = Thyra::createMember(space_);
  Thyra::V_S(x0.ptr(), 0.0);
  nominal_.set_x(x0);

  MEB::OutArgsSetup<double> out;
  out.setModelEvalDescription("Glossa Q1-P0 residual");
  out.set_Np_Ng(Np, Ng);
  out.setSupports(MEB::OUT_ARG_f);
  out.setSupports(MEB::OUT_ARG_W_op);
  if (groups_ > 0) out.setSupports(MEB::OUT_ARG_DfDp, kNeuralInputs, MEB::DerivativeSupport(MEB::DERIV_MV_BY_COL));
  if (Ng > 0) out.setSupports(MEB::OUT_ARG_DgDx, 0, MEB::DerivativeSupport(MEB::DERIV_TRANS_MV_BY_ROW));
  prototypeOutArgs_ = out;
}

void ModelEvaluator::setMultipliers(const std::vector<double> &lambda) {
  TEUCHOS_TEST_FOR_EXCEPTION(lambda.size() != lambda_.size(), std::invalid_argument,
                             "setMultipliers: " << lambda.size() << " values for " << lambda_.size() << " elements");
  lambda_ = lambda;
  tangentCached_ = false;
}

MEB::InArgs<double> ModelEvaluator::getNominalValues() const {
  MEB::InArgs<double> nominal = nominal_;
  auto time = Thyra::createMember(timeSpace_);
  Thyra::set_ele(0, time_, time.ptr());
  nominal.set_p(kTime, time);
  auto lambda = Thyra::createMember(elementSpace_);
  auto data = Extract::getTpetraVector(lambda)->getDataNonConst(0);
  std::copy(lambda_.begin(), lambda_.end(), data.begin());
  nominal.set_p(kMultipliers, lambda);
  if (groups_ > 0) {
    auto inputs = Thyra::createMember(inputSpace_);
    for (int g = 0; g < groups_; ++g) Thyra::set_ele(g, history_->trialInput()[g], inputs.ptr());
    nominal.set_p(kNeuralInputs, inputs);
  }
  return nominal;
}

Teuchos::RCP<const Thyra::VectorSpaceBase<double>> ModelEvaluator::get_p_space(int l) const {
  TEUCHOS_TEST_FOR_EXCEPTION(l < 0 || l >= prototypeInArgs_.Np(), std::out_of_range, "no model parameter " << l);
  return l == kTime ? timeSpace_ : l == kMultipliers ? elementSpace_ : inputSpace_;
}

Teuchos::RCP<const Teuchos::Array<std::string>> ModelEvaluator::get_p_names(int l) const {
  TEUCHOS_TEST_FOR_EXCEPTION(l < 0 || l >= prototypeInArgs_.Np(), std::out_of_range, "no model parameter " << l);
  if (l == kTime) return Teuchos::rcp(new Teuchos::Array<std::string>(1, "time"));
  if (l == kMultipliers) return Teuchos::null; // one per element: unnamed
  Teuchos::Array<std::string> names;
  for (const auto &g : assembler_->scene().muscles.groups) names.push_back("input " + g.name);
  return Teuchos::rcp(new Teuchos::Array<std::string>(names));
}

Teuchos::RCP<const Thyra::VectorSpaceBase<double>> ModelEvaluator::get_g_space(int j) const {
  TEUCHOS_TEST_FOR_EXCEPTION(j != 0 || responseSpace_.is_null(), std::out_of_range, "no model response " << j);
  return responseSpace_;
}

void ModelEvaluator::resetIterates(const Vector &u) {
  tangentCached_ = false;
  // With pressures as unknowns the kernel's volumetric energy is zero and the element pressure is
  // the multiplier itself: the three-field iterates would carry nothing.
  mixed_ = assembler_->scene().formulation == model::ElementFormulation::Q1P0 && pressure_.is_null();
  if (!pressure_.is_null()) pressure_->pending = false;
  if (mixed_) bases_ = assembler_->mixedBases(u, lambda_, nullptr);
}

void ModelEvaluator::advanceIterates(const Vector &u) {
  if (!pressure_.is_null()) pressure_->commit(lambda_);
  if (mixed_) bases_ = assembler_->mixedBases(u, lambda_, &bases_);
}

Teuchos::RCP<Thyra::LinearOpBase<double>> ModelEvaluator::create_W_op() const {
  // One matrix serves every W: NOX asks for it once per group.
  return Thyra::tpetraLinearOp<double, LO, GO, Node>(space_, space_, matrix_);
}

namespace {
// Sets the groups' trial activations to those of other neural inputs for the life of one
// evaluation, and restores them.
class InputsForOneEvaluation {
public:
  InputsForOneEvaluation(model::MuscleHistory *history, const Thyra::VectorBase<double> *inputs, int groups)
      : history_(inputs ? history : nullptr) {
    if (!history_) return;
    for (int g = 0; g < groups; ++g) {
      saved_.push_back(history_->groupActivation(g));
      history_->setTrialActivation(g, history_->trialActivationForInput(g, std::clamp(Thyra::get_ele(*inputs, g), 0.0, 1.0)));
    }
  }
  ~InputsForOneEvaluation() {
    if (history_)
      for (std::size_t g = 0; g < saved_.size(); ++g) history_->setTrialActivation(static_cast<int>(g), saved_[g]);
  }
  InputsForOneEvaluation(const InputsForOneEvaluation &) = delete;
  InputsForOneEvaluation &operator=(const InputsForOneEvaluation &) = delete;

private:
  model::MuscleHistory *history_;
  std::vector<double> saved_;
};
} // namespace

void ModelEvaluator::evalModelImpl(const MEB::InArgs<double> &in, const MEB::OutArgs<double> &out) const {
  const auto start = std::chrono::steady_clock::now();
  const Teuchos::RCP<const Vector> x = Extract::getConstTpetraVector(in.get_x());
  const Teuchos::RCP<Thyra::VectorBase<double>> fThyra = out.get_f();
  const Teuchos::RCP<Thyra::LinearOpBase<double>> W = out.get_W_op();
  Teuchos::RCP<Vector> f = fThyra.is_null() ? Teuchos::null : Extract::getTpetraVector(fThyra);
  const Teuchos::RCP<const Thyra::VectorBase<double>> p = in.get_p(kTime);
  const double time = p.is_null() ? time_ : Thyra::get_ele(*p, 0);
  // The multipliers given (p1), else the nominal ones.
  std::vector<double> givenLambda;
  if (const auto given = in.get_p(kMultipliers); !given.is_null()) {
    const auto data = Extract::getConstTpetraVector(given)->getData(0);
    givenLambda.assign(data.begin(), data.end());
  }
  const bool lambdaGiven = !in.get_p(kMultipliers).is_null();
  const std::vector<double> &lambdaIn = lambdaGiven ? givenLambda : lambda_;
  const Teuchos::RCP<const Thyra::VectorBase<double>> inputs = groups_ > 0 ? in.get_p(kNeuralInputs) : Teuchos::null;
  const InputsForOneEvaluation atInputs(history_, inputs.get(), groups_);

  if (out.Ng() > 0 && (!out.get_g(0).is_null() || !out.get_DgDx(0).isEmpty())) evaluateResponse(*x, out);
  if (groups_ > 0 && !out.get_DfDp(kNeuralInputs).isEmpty())
    evaluateInputDerivative(*x, time, lambdaIn, inputs.get(), *out.get_DfDp(kNeuralInputs).getMultiVector());

  FEMatrix *K = nullptr;
  if (!W.is_null()) {
    auto op = Extract::getTpetraOperator(W);
    K = dynamic_cast<FEMatrix *>(op.get());
    TEUCHOS_TEST_FOR_EXCEPTION(K == nullptr, std::logic_error, "W_op is not the model's FECrsMatrix");
  }
  if (f.is_null() && !K) return;
  TEUCHOS_TEST_FOR_EXCEPTION(!pressure_.is_null() && (lambdaGiven || !inputs.is_null()), std::logic_error,
                             "with pressure unknowns the multipliers and inputs are the nominal ones");
  if (K && !pressure_.is_null()) {
    // A tangent at a trial point: the point is the iterate, so its pressure is too.
    pressure_->commit(lambda_);
    pressure_->linearise(*assembler_, *x, lambda_);
  }
  const std::vector<double> &lambda = pressure_.is_null() ? lambdaIn : pressure_->trialPressure(lambda_);
  // Only at the nominal inputs may the tangent be kept for the next request.
  const bool nominal = inputs.is_null();
  if (K == matrix_.get() && f.is_null() && nominal && tangentIsCachedAt(*x, time, lambda)) {
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
  const bool withTangent = !f.is_null() && !K && pressure_.is_null() && nominal;
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

void ModelEvaluator::evaluateResponse(const Vector &x, const MEB::OutArgs<double> &out) const {
  TEUCHOS_TEST_FOR_EXCEPTION(responseSpace_.is_null(), std::logic_error, "the model has no response nodes");
  if (const auto g = out.get_g(0); !g.is_null()) {
    const std::vector<double> all = assembler_->gatherDisplacement(x);
    for (std::size_t n = 0; n < responseNodes_.size(); ++n)
      for (int c = 0; c < 3; ++c)
        Thyra::set_ele(static_cast<Thyra::Ordinal>(3 * n + c), all[3 * responseNodes_[n] + c], g.ptr());
  }
  if (const auto dgdx = out.get_DgDx(0).getMultiVector(); !dgdx.is_null()) {
    // Gradient form: column j is d g_j / dx, one at the dof of node j / 3, component j % 3.
    const auto D = Extract::getTpetraMultiVector(dgdx);
    D->putScalar(0.0);
    const Map &owned = *assembler_->ownedMap();
    for (std::size_t n = 0; n < responseNodes_.size(); ++n)
      for (int c = 0; c < 3; ++c) {
        const LO row = owned.getLocalElement(static_cast<GO>(assembler_->layout().dof(responseNodes_[n], c)));
        if (row != Teuchos::OrdinalTraits<LO>::invalid()) D->replaceLocalValue(row, 3 * n + c, 1.0);
      }
  }
}

void ModelEvaluator::evaluateInputDerivative(const Vector &x, double time, const std::vector<double> &lambda,
                                             const Thyra::VectorBase<double> *inputs,
                                             Thyra::MultiVectorBase<double> &dfdp) const {
  // Column g: d f / d alpha_g (d alpha_g / d u_g) at this evaluation's inputs. d f / d alpha by
  // one-sided three-point differences, which keep alpha in [0, 1], in the group's trial
  // activation (the point laws and the external muscles re-solve their lambda_c at every
  // evaluation, so no analytic alpha-derivative is needed); step 1e-5, where the truncation
  // O(h^2) and the round-off O(eps / h) of the residual's scale balance.
  constexpr double h = 1e-5;
  const double weights[3] = {-1.5, 2.0, -0.5}; // d/da at a of f(a), f(a + s h), f(a + 2 s h)
  const auto D = Extract::getTpetraMultiVector(Teuchos::rcpFromRef(dfdp));
  D->putScalar(0.0);
  Vector f(assembler_->ownedMap());
  for (int g = 0; g < groups_; ++g) {
    const double alpha = history_->groupActivation(g);
    // At the input that gave alpha: the given one (InputsForOneEvaluation) or the begun step's.
    const double input = inputs ? std::clamp(Thyra::get_ele(*inputs, g), 0.0, 1.0) : history_->trialInput()[g];
    const double dalphadu = history_->trialActivationInputDerivative(g, input);
    const double side = alpha + 2.0 * h <= 1.0 ? 1.0 : -1.0;
    auto column = D->getVectorNonConst(static_cast<std::size_t>(g));
    for (int k = 0; k < 3; ++k) {
      history_->setTrialActivation(g, alpha + side * k * h);
      const auto status = assembler_->assemble(x, time, lambda, nullptr, &f, nullptr);
      if (!status.valid) {
        history_->setTrialActivation(g, alpha);
        throw std::runtime_error("DfDp: the state is inadmissible");
      }
      column->update(weights[k] * side / h * dalphadu, f, 1.0);
    }
    history_->setTrialActivation(g, alpha);
  }
}

bool ModelEvaluator::tangentIsCachedAt(const Vector &x, double time, const std::vector<double> &lambda) const {
  int same = tangentCached_ && tangentTime_ == time && tangentLambda_ == lambda ? 1 : 0;
  if (same) {
    auto a = x.getData(0), b = tangentPoint_->getData(0);
    for (std::size_t i = 0; i < x.getLocalLength() && same; ++i) same = a[i] == b[i] ? 1 : 0;
  }
  int all = 0;
  Teuchos::reduceAll(*x.getMap()->getComm(), Teuchos::REDUCE_MIN, same, Teuchos::outArg(all));
  return all == 1;
}

} // namespace glossa::assembly
