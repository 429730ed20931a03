#include "solvers/control/ControlSensitivity.hpp"

#include "assembly/TimeSplit.hpp"

#include <optional>

#include <Thyra_DetachedMultiVectorView.hpp>
#include <Thyra_MultiVectorStdOps.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

namespace glossa::solvers {

using Extract = Thyra::TpetraOperatorVectorExtraction<double, assembly::LO, assembly::GO, assembly::Node>;
using MEB = Thyra::ModelEvaluatorBase;

ControlPointSensitivity controlPointSensitivity(const NewtonSolver &newton, const assembly::Vector &u,
                                                const std::vector<int> &groups) {
  std::optional<assembly::PartTimer> derivativesTimer(assembly::TimedPart::inputDerivatives);
  assembly::ModelEvaluator &model = newton.model();
  const auto xSpace = model.get_x_space();
  const auto ownedMap = u.getMap();
  MEB::InArgs<double> in = model.getNominalValues();
  in.set_x(Thyra::createConstVector<double, assembly::LO, assembly::GO, assembly::Node>(Teuchos::rcpFromRef(u), xSpace));
  MEB::OutArgs<double> out = model.createOutArgs();
  const auto dfdp = Thyra::createMembers(model.get_f_space(), model.get_p_space(assembly::ModelEvaluator::kNeuralInputs));
  const auto dgdx = Thyra::createMembers(xSpace, model.get_g_space(0));
  out.set_DfDp(assembly::ModelEvaluator::kNeuralInputs, MEB::Derivative<double>(dfdp, MEB::DERIV_MV_BY_COL));
  out.set_DgDx(0, MEB::Derivative<double>(dgdx, MEB::DERIV_TRANS_MV_BY_ROW));
  model.evalModel(in, out);
  derivativesTimer.reset();

  // W X = -DfDp for the columns asked.
  const auto n = groups.size();
  const auto DfDp = Extract::getConstTpetraMultiVector(dfdp);
  assembly::MultiVector rhs(ownedMap, n);
  const auto solution = Teuchos::rcp(new assembly::MultiVector(ownedMap, n));
  assembly::MultiVector &x = *solution;
  for (std::size_t j = 0; j < n; ++j)
    rhs.getVectorNonConst(j)->update(-1.0, *DfDp->getVector(static_cast<std::size_t>(groups[j])), 0.0);
  ControlPointSensitivity result;
  result.krylovIterations = newton.solveSensitivities(u, rhs, x);
  result.responses = solution;

  // dg/dp = DgDx^T X (gradient form: DgDx's columns are d g_i / dx).
  const auto X = Thyra::createMultiVector<double, assembly::LO, assembly::GO, assembly::Node>(Teuchos::rcpFromRef(x), xSpace);
  const auto S = Thyra::createMembers(dgdx->domain(), static_cast<int>(n));
  Thyra::apply(*dgdx, Thyra::TRANS, *X, S.ptr());
  const Thyra::ConstDetachedMultiVectorView<double> view(*S);
  result.dxdu.resize(view.subDim(), static_cast<Eigen::Index>(n));
  for (Thyra::Ordinal i = 0; i < view.subDim(); ++i)
    for (std::size_t j = 0; j < n; ++j) result.dxdu(i, static_cast<Eigen::Index>(j)) = view(i, static_cast<Thyra::Ordinal>(j));
  return result;
}

} // namespace glossa::solvers
