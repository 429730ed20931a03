#include "assembly/ModelEvaluator.hpp"

#include "assembly/TimeSplit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <Teuchos_CommHelpers.hpp>
#include <Thyra_DefaultSpmdVectorSpace.hpp>
#include <Thyra_DefaultScaledAdjointLinearOp.hpp>
#include <Thyra_DefaultProductVectorSpace.hpp>
#include <Thyra_DefaultProductVector.hpp>
#include <Thyra_DefaultDiagonalLinearOp.hpp>
#include <Thyra_DefaultBlockedLinearOp.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

namespace glossa::assembly {

using Extract = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>;
using MEB = Thyra::ModelEvaluatorBase;

ModelEvaluator::ModelEvaluator(Teuchos::RCP<const Assembler> assembler,
                               Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> solverFactory,
                               model::MuscleHistory *history, std::vector<mesh::NodeId> responseNodes)
    : assembler_(std::move(assembler)), results_(*assembler_), solverFactory_(std::move(solverFactory)),
      history_(history), responseNodes_(std::move(responseNodes)) {
  uSpace_ = Thyra::createVectorSpace<double, LO, GO, Node>(assembler_->layout().ownedMap());
  space_ = uSpace_;
  matrix_ = assembler_->createMatrix();
  lambda_.assign(assembler_->layout().numLocalElements(), 0.0);
  const auto comm = Thyra::convertTpetraToThyraComm(assembler_->layout().ownedMap()->getComm());
  timeSpace_ = Thyra::locallyReplicatedDefaultSpmdVectorSpace<double>(comm, 1);
  elementSpace_ = Thyra::createVectorSpace<double, LO, GO, Node>(assembler_->layout().elementMap());
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

void ModelEvaluator::setMixedPressure(Teuchos::RCP<MixedPressureState> state) {
  pressure_ = std::move(state);
  if (pressure_.is_null()) {
    space_ = uSpace_;
    return;
  }
  space_ = Thyra::productVectorSpace<double>(Teuchos::tuple(uSpace_, elementSpace_)());
  pressure_->initialise(*assembler_);
  auto x0 = Thyra::createMember(space_);
  Thyra::V_S(x0.ptr(), 0.0);
  nominal_.set_x(x0);
}

Teuchos::RCP<Thyra::VectorBase<double>> ModelEvaluator::initialGuess(const Vector &u) const {
  auto uCopy = Teuchos::rcp(new Vector(u, Teuchos::Copy));
  auto xu = Thyra::createVector(Teuchos::RCP<Vector>(uCopy), uSpace_);
  if (pressure_.is_null()) return xu;
  auto xp = Thyra::createMember(elementSpace_);
  auto data = Extract::getTpetraVector(xp)->getDataNonConst(0);
  for (std::size_t i = 0; i < lambda_.size(); ++i) data[i] = lambda_[i] / pressure_->sigma[i];
  const auto product = Teuchos::rcp_dynamic_cast<const Thyra::DefaultProductVectorSpace<double>>(space_, true);
  return Thyra::defaultProductVector<double>(product, Teuchos::tuple<Teuchos::RCP<Thyra::VectorBase<double>>>(xu, xp)());
}

Teuchos::RCP<const Vector> ModelEvaluator::displacementOf(const Thyra::VectorBase<double> &x) const {
  const Thyra::VectorBase<double> *u = &x;
  Teuchos::RCP<const Thyra::VectorBase<double>> block;
  if (!pressure_.is_null()) {
    block = dynamic_cast<const Thyra::ProductVectorBase<double> &>(x).getVectorBlock(0);
    u = block.get();
  }
  return Extract::getConstTpetraVector(Teuchos::rcpFromRef(*u));
}

void ModelEvaluator::acceptSolution(const Thyra::VectorBase<double> &x, Vector &u) {
  // u entered the solve with the prescribed values at the constrained dofs: they stay exact.
  assembler_->assignFreeDofs(*displacementOf(x), u);
  if (pressure_.is_null()) return;
  const auto p = dynamic_cast<const Thyra::ProductVectorBase<double> &>(x).getVectorBlock(1);
  const auto data = Extract::getConstTpetraVector(p)->getData(0);
  for (std::size_t i = 0; i < lambda_.size(); ++i) lambda_[i] = pressure_->sigma[i] * data[i];
}

void ModelEvaluator::setTime(double t) {
  time_ = t;
  tangentCached_ = false;
  for (const auto &contact : assembler_->scene().contacts)
    if (contact.motion) contact.motion->setTime(t);
}

void ModelEvaluator::beginStep(double time, double dt, const std::vector<double> &inputs) {
  TEUCHOS_TEST_FOR_EXCEPTION(!history_ && !inputs.empty(), std::logic_error, "neural inputs without a muscle history");
  setTime(time);
  if (history_) history_->beginStep(time, dt, inputs);
  if (inertia_) inertia_->beginStep(dt);
  // As lambda_c: a step's solves start from the committed contact multipliers.
  for (const auto &contact : assembler_->scene().contacts)
    if (contact.state) contact.state->rollBack();
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
  if (accepted_.is_null() || !accepted_->getMap()->isSameAs(*u.getMap())) accepted_ = Teuchos::rcp(new Vector(u.getMap()));
  accepted_->assign(u);
  // With pressures as unknowns the kernel's volumetric energy is zero and the element pressure is
  // the multiplier itself: the three-field iterates would carry nothing.
  mixed_ = assembler_->scene().formulation == model::ElementFormulation::Q1P0 && pressure_.is_null();
  const PartTimer timer(TimedPart::threeFieldBases);
  if (mixed_) bases_ = assembler_->mixedBases(u, lambda_, nullptr);
}

void ModelEvaluator::advanceIterates(const Vector &u) {
  const PartTimer timer(TimedPart::threeFieldBases);
  if (mixed_) bases_ = assembler_->mixedBases(u, lambda_, &bases_);
  if (!accepted_.is_null() && accepted_->getMap()->isSameAs(*u.getMap())) accepted_->assign(u);
}

bool ModelEvaluator::updateForecastsConvergence(const Vector &x) const {
  if (!forecast_ || accepted_.is_null() || !accepted_->getMap()->isSameAs(*x.getMap())) return false;
  if (update_.is_null() || !update_->getMap()->isSameAs(*x.getMap())) update_ = Teuchos::rcp(new Vector(x.getMap()));
  update_->update(1.0, x, -1.0, *accepted_, 0.0);
  // No update yet (the solve's first residual): its tangent is the first Newton step's.
  if (update_->normInf() == 0.0) return false;
  return forecast_(*update_, x);
}

Teuchos::RCP<Thyra::LinearOpBase<double>> ModelEvaluator::create_W_op() const {
  // One matrix serves every W: NOX asks for it once per group. Mixed: a blocked operator whose
  // blocks every evaluation of W fills (K this matrix, the others the pressure state's).
  if (!pressure_.is_null()) return Thyra::defaultBlockedLinearOp<double>();
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
  const Teuchos::RCP<const Vector> x = displacementOf(*in.get_x());
  const Teuchos::RCP<Thyra::VectorBase<double>> fThyra = out.get_f();
  const Teuchos::RCP<Thyra::LinearOpBase<double>> W = out.get_W_op();
  Teuchos::RCP<Vector> f = fThyra.is_null() || !pressure_.is_null() ? Teuchos::null : Extract::getTpetraVector(fThyra);
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

  if (!pressure_.is_null()) {
    TEUCHOS_TEST_FOR_EXCEPTION(lambdaGiven || !inputs.is_null(), std::logic_error,
                               "with pressure unknowns the multipliers and inputs are the nominal ones");
    TEUCHOS_TEST_FOR_EXCEPTION(inertia_ != nullptr, std::logic_error,
                               "inertia with pressure unknowns is refused by the run's checks");
    evaluateMixed(in, out, time);
    assemblySeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return;
  }
  FEMatrix *K = nullptr;
  if (!W.is_null()) {
    auto op = Extract::getTpetraOperator(W);
    K = dynamic_cast<FEMatrix *>(op.get());
    TEUCHOS_TEST_FOR_EXCEPTION(K == nullptr, std::logic_error, "W_op is not the model's FECrsMatrix");
  }
  if (f.is_null() && !K) return;
  const std::vector<double> &lambda = lambdaIn;
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
  bool withTangent = !f.is_null() && !K && nominal;
  if (withTangent && updateForecastsConvergence(*x)) {
    withTangent = false;
    ++residualOnlyPasses_;
  }
  Vector fScratch(assembler_->layout().ownedMap());
  if (withTangent) {
    lastStatus_ = assembler_->assemble(*x, time, lambda, mixed_ ? &bases_ : nullptr, f.get(), matrix_.get(),
                                       Assembler::BasePoint::trial, elementCorrection());
    if (inertia_ && lastStatus_.valid) inertia_->addTo(*x, f.get(), matrix_.get());
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
                                       f.is_null() ? (K ? &fScratch : nullptr) : f.get(), K,
                                       Assembler::BasePoint::byRequest, elementCorrection());
    if (inertia_ && lastStatus_.valid) inertia_->addTo(*x, f.get(), K);
  }
  if (!lastStatus_.valid && !f.is_null()) f->putScalar(std::numeric_limits<double>::quiet_NaN());
  if (!f.is_null()) ++residualEvaluations_;
  if (K || withTangent) ++tangentEvaluations_;
  assemblySeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void ModelEvaluator::evaluateMixed(const MEB::InArgs<double> &in, const MEB::OutArgs<double> &out, double time) const {
  const auto &x = dynamic_cast<const Thyra::ProductVectorBase<double> &>(*in.get_x());
  const Teuchos::RCP<const Vector> u = Extract::getConstTpetraVector(x.getVectorBlock(0));
  const auto scaled = Extract::getConstTpetraVector(x.getVectorBlock(1))->getData(0);
  const std::vector<double> &sigma = pressure_->sigma;
  std::vector<double> p(sigma.size());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = sigma[i] * scaled[i];
  const auto fThyra = out.get_f();
  Teuchos::RCP<Thyra::ProductVectorBase<double>> f =
      fThyra.is_null() ? Teuchos::null : Teuchos::rcp_dynamic_cast<Thyra::ProductVectorBase<double>>(fThyra, true);
  const auto W = out.get_W_op();
  Vector fScratch(assembler_->layout().ownedMap());
  Teuchos::RCP<Vector> fu = f.is_null() ? Teuchos::null : Extract::getTpetraVector(f->getNonconstVectorBlock(0));
  // The displacement rows at the pressures p (the kernel's volumetric energy is zero: the element
  // pressure is p_e itself), with K at fixed pressure when W is asked.
  lastStatus_ = assembler_->assemble(*u, time, p, nullptr, fu.is_null() ? (W.is_null() ? nullptr : &fScratch) : fu.get(),
                                     W.is_null() ? nullptr : matrix_.get());
  // The pressure rows: sigma_e (v_e - V_e theta_phys(p_e)), and the blocks.
  pressure_->linearise(*assembler_, *u, p);
  // The round-off floor of the residual (NewtonSolver): its pressure rows' terms, of size
  // sigma_e V_e, cancel; and a node's displacement rows sum the pressure forces p_e B_e of up to
  // 8 elements, which cancel there against the deviatoric ones. With kappa = 0 nothing else in the
  // kernel's scale is of their size (measured on the isometric block at full activation: the
  // residual stalled at 8-18 eps of the kernel's scale alone).
  double local = pressure_->constraintTerms, global = 0.0;
  const auto &B = *pressure_->coupling.volumeGradient;
  for (std::size_t i = 0; i < sigma.size(); ++i) {
    typename CrsMatrix::local_inds_host_view_type columns;
    typename CrsMatrix::values_host_view_type values;
    B.getLocalRowView(static_cast<LO>(i), columns, values);
    double row = 0.0;
    for (std::size_t k = 0; k < values.extent(0); ++k) row += values(k) * values(k);
    const double nodalSum = 8.0 * std::abs(p[i]) * std::sqrt(row) / sigma[i];
    local += nodalSum * nodalSum;
  }
  Teuchos::reduceAll(*assembler_->layout().comm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  lastStatus_.forceScale = std::sqrt(lastStatus_.forceScale * lastStatus_.forceScale + global);
  if (!f.is_null()) {
    Extract::getTpetraVector(f->getNonconstVectorBlock(1))->assign(*pressure_->constraintResidual);
    if (!lastStatus_.valid) Thyra::V_S(fThyra.ptr(), std::numeric_limits<double>::quiet_NaN());
    ++residualEvaluations_;
  }
  if (!W.is_null()) {
    auto blocked = Teuchos::rcp_dynamic_cast<Thyra::PhysicallyBlockedLinearOpBase<double>>(W, true);
    const auto product = Teuchos::rcp_dynamic_cast<const Thyra::ProductVectorSpaceBase<double>>(space_, true);
    auto B = Thyra::constTpetraLinearOp<double, LO, GO, Node>(elementSpace_, uSpace_, pressure_->coupling.volumeGradient);
    auto minusC = Teuchos::rcp(new Vector(*pressure_->compliance, Teuchos::Copy));
    minusC->scale(-1.0);
    blocked->beginBlockFill(product, product);
    blocked->setBlock(0, 0, Thyra::tpetraLinearOp<double, LO, GO, Node>(uSpace_, uSpace_, matrix_));
    blocked->setBlock(0, 1, Thyra::adjoint<double>(B));
    blocked->setBlock(1, 0, B);
    blocked->setBlock(1, 1, Thyra::diagonal<double>(Thyra::createVector(Teuchos::RCP<Vector>(minusC), elementSpace_)));
    blocked->endBlockFill();
    ++tangentEvaluations_;
  }
}

void ModelEvaluator::evaluateResponse(const Vector &x, const MEB::OutArgs<double> &out) const {
  TEUCHOS_TEST_FOR_EXCEPTION(responseSpace_.is_null(), std::logic_error, "the model has no response nodes");
  if (const auto g = out.get_g(0); !g.is_null()) {
    const std::vector<double> all = results_.gatherDisplacement(x);
    for (std::size_t n = 0; n < responseNodes_.size(); ++n)
      for (int c = 0; c < 3; ++c)
        Thyra::set_ele(static_cast<Thyra::Ordinal>(3 * n + c), all[3 * responseNodes_[n] + c], g.ptr());
  }
  if (const auto dgdx = out.get_DgDx(0).getMultiVector(); !dgdx.is_null()) {
    // Gradient form: column j is d g_j / dx, one at the dof of node j / 3, component j % 3.
    const auto D = Extract::getTpetraMultiVector(dgdx);
    D->putScalar(0.0);
    const Map &owned = *assembler_->layout().ownedMap();
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
  // O(h^2) and the round-off O(eps / h) of the residual's scale balance. Only the elements with a
  // fibre family of the group are evaluated (the loads whole, for external muscles): the others'
  // forces are the same numbers at every alpha and cancel (the weights sum to 0). On the tongue
  // that is 4.5 element passes per sensitivity instead of 33.
  constexpr double h = 1e-5;
  const double weights[3] = {-1.5, 2.0, -0.5}; // d/da at a of f(a), f(a + s h), f(a + 2 s h)
  const auto D = Extract::getTpetraMultiVector(Teuchos::rcpFromRef(dfdp));
  D->putScalar(0.0);
  Vector f(assembler_->layout().ownedMap());
  for (int g = 0; g < groups_; ++g) {
    const double alpha = history_->groupActivation(g);
    // At the input that gave alpha: the given one (InputsForOneEvaluation) or the begun step's.
    const double input = inputs ? std::clamp(Thyra::get_ele(*inputs, g), 0.0, 1.0) : history_->trialInput()[g];
    const double dalphadu = history_->trialActivationInputDerivative(g, input);
    const double side = alpha + 2.0 * h <= 1.0 ? 1.0 : -1.0;
    auto column = D->getVectorNonConst(static_cast<std::size_t>(g));
    const std::vector<char> elements = groupElements(g);
    for (int k = 0; k < 3; ++k) {
      history_->setTrialActivation(g, alpha + side * k * h);
      const auto status = assembler_->assemble(x, time, lambda, nullptr, &f, nullptr, Assembler::BasePoint::byRequest,
                                               nullptr, &elements);
      if (!status.valid) {
        history_->setTrialActivation(g, alpha);
        throw std::runtime_error("DfDp: the state is inadmissible");
      }
      column->update(weights[k] * side / h * dalphadu, f, 1.0);
    }
    history_->setTrialActivation(g, alpha);
  }
}

std::vector<char> ModelEvaluator::groupElements(int group) const {
  const model::MuscleArchitecture &muscles = assembler_->scene().muscles;
  const auto &local = assembler_->layout().localElements;
  std::vector<char> in(local.size(), 0);
  for (std::size_t i = 0; i < local.size(); ++i) in[i] = muscles.carriesGroup(static_cast<std::size_t>(local[i]), group) ? 1 : 0;
  return in;
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
