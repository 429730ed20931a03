#include "solvers/linear/CollectivePreconditioner.hpp"

#include <optional>
#include <stdexcept>
#include <string>

#include <Thyra_TpetraLinearOp.hpp>

#include "assembly/RankAgreement.hpp"
#include "assembly/TpetraTypes.hpp"

namespace glossa::solvers {

namespace {
using Base = Thyra::PreconditionerFactoryBase<double>;
using TpetraOp = Thyra::TpetraLinearOp<double, assembly::LO, assembly::GO, assembly::Node>;

class CollectivePreconditionerFactory final : public Base {
public:
  explicit CollectivePreconditionerFactory(Teuchos::RCP<Base> inner) : inner_(std::move(inner)) {}

  bool isCompatible(const Thyra::LinearOpSourceBase<double> &source) const override {
    return inner_->isCompatible(source);
  }
  Teuchos::RCP<Thyra::PreconditionerBase<double>> createPrec() const override { return inner_->createPrec(); }
  void initializePrec(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> &source,
                      Thyra::PreconditionerBase<double> *prec, const Thyra::ESupportSolveUse use) const override {
    std::optional<std::string> mine;
    try {
      inner_->initializePrec(source, prec, use);
    } catch (const std::exception &e) {
      mine = e.what();
    }
    // Only a Tpetra operator says which ranks share it; anything else fails where it failed.
    const auto op = Teuchos::rcp_dynamic_cast<const TpetraOp>(source->getOp());
    if (op.is_null()) {
      if (mine) throw std::runtime_error("preconditioner set-up failed: " + *mine);
      return;
    }
    const auto failure = assembly::failureOnAnyRank(*op->getConstTpetraOperator()->getRangeMap()->getComm(), mine);
    if (!failure) return;
    if (failure->ranks == 1) throw std::runtime_error("preconditioner set-up failed: " + failure->reason);
    throw std::runtime_error("preconditioner set-up failed " + failure->where() + ": " + failure->reason);
  }
  void uninitializePrec(Thyra::PreconditionerBase<double> *prec,
                        Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> *source,
                        Thyra::ESupportSolveUse *use) const override {
    inner_->uninitializePrec(prec, source, use);
  }
  bool applySupportsConj(Thyra::EConj conj) const override { return inner_->applySupportsConj(conj); }
  bool applyTransposeSupportsConj(Thyra::EConj conj) const override { return inner_->applyTransposeSupportsConj(conj); }

  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList> &list) override { inner_->setParameterList(list); }
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override { return inner_->getNonconstParameterList(); }
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override { return inner_->unsetParameterList(); }
  Teuchos::RCP<const Teuchos::ParameterList> getParameterList() const override { return inner_->getParameterList(); }
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override { return inner_->getValidParameters(); }
  std::string description() const override { return "collective " + inner_->description(); }

private:
  Teuchos::RCP<Base> inner_;
};
} // namespace

Teuchos::RCP<Base> collectivePreconditioner(const Teuchos::RCP<Base> &inner) {
  if (inner.is_null()) return inner;
  return Teuchos::rcp(new CollectivePreconditionerFactory(inner));
}

void makePreconditionerCollective(Thyra::LinearOpWithSolveFactoryBase<double> &solver) {
  if (!solver.acceptsPreconditionerFactory() || solver.getPreconditionerFactory().is_null()) return;
  Teuchos::RCP<Base> inner;
  std::string name;
  solver.unsetPreconditionerFactory(&inner, &name);
  solver.setPreconditionerFactory(collectivePreconditioner(inner), name);
}

} // namespace glossa::solvers
