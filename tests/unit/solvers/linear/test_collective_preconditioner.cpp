// The collective preconditioner set-up, on 1 rank and under mpiexec on 2: a set-up that throws on
// the last rank alone (as Ifpack2's Chebyshev on a coarse level MueLu gathered onto one rank did)
// throws on every rank, naming that rank and its reason; a set-up that succeeds everywhere is
// the inner one's; and the run's linear solver is built with its preconditioner so wrapped.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include <Thyra_DefaultLinearOpSource.hpp>
#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_Core.hpp>

#include "solvers/linear/CollectivePreconditioner.hpp"
#include "solvers/linear/LinearSolverFactory.hpp"

using namespace glossa;
using namespace glossa::solvers;

namespace {
const auto kSmootherFailure = "Ifpack2::Chebyshev::compute: Estimation of the max eigenvalue of D^{-1} A failed";

bool onLastRank() {
  const auto comm = Tpetra::getDefaultComm();
  return comm->getRank() == comm->getSize() - 1;
}

// A set-up that fails where `fails` says.
class FakePreconditioner final : public Thyra::PreconditionerFactoryBase<double> {
public:
  explicit FakePreconditioner(bool fails) : fails_(fails) {}
  mutable int setups = 0;
  bool isCompatible(const Thyra::LinearOpSourceBase<double> &) const override { return true; }
  Teuchos::RCP<Thyra::PreconditionerBase<double>> createPrec() const override {
    return Teuchos::rcp(new Thyra::DefaultPreconditioner<double>());
  }
  void initializePrec(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> &source,
                      Thyra::PreconditionerBase<double> *prec, const Thyra::ESupportSolveUse) const override {
    ++setups;
    if (fails_) throw std::runtime_error(kSmootherFailure);
    dynamic_cast<Thyra::DefaultPreconditioner<double> &>(*prec).initializeUnspecified(source->getOp());
  }
  void uninitializePrec(Thyra::PreconditionerBase<double> *, Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> *,
                        Thyra::ESupportSolveUse *) const override {}
  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList> &list) override { list_ = list; }
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override { return list_; }
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override { return std::exchange(list_, Teuchos::null); }

private:
  bool fails_;
  Teuchos::RCP<Teuchos::ParameterList> list_;
};

// The identity on 4 rows per rank, as Thyra sees a Tpetra matrix.
Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> identitySource() {
  const auto comm = Tpetra::getDefaultComm();
  const auto map = Teuchos::rcp(new assembly::Map(4 * comm->getSize(), 0, comm));
  auto A = Teuchos::rcp(new assembly::CrsMatrix(map, 1));
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const assembly::GO row = map->getGlobalElement(static_cast<assembly::LO>(i));
    A->insertGlobalValues(row, Teuchos::tuple(row), Teuchos::tuple(1.0));
  }
  A->fillComplete();
  const auto op = Thyra::createConstLinearOp<double, assembly::LO, assembly::GO, assembly::Node>(
      Teuchos::RCP<const assembly::CrsMatrix>(A));
  return Thyra::defaultLinearOpSource<double>(op);
}
} // namespace

TEST(CollectivePreconditioner, ASetUpThatFailsOnOneRankFailsOnEveryRankWithItsReason) {
  const auto inner = Teuchos::rcp(new FakePreconditioner(onLastRank()));
  const auto factory = collectivePreconditioner(inner);
  const auto prec = factory->createPrec();
  const int ranks = Tpetra::getDefaultComm()->getSize();
  const std::string expected = ranks == 1 ? std::string("preconditioner set-up failed: ") + kSmootherFailure
                                          : "preconditioner set-up failed on rank " + std::to_string(ranks - 1) + " of " +
                                                std::to_string(ranks) + ": " + kSmootherFailure;
  try {
    factory->initializePrec(identitySource(), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
    FAIL() << "no rank threw";
  } catch (const std::runtime_error &e) {
    EXPECT_EQ(std::string(e.what()), expected);
  }
  EXPECT_EQ(inner->setups, 1);
}

TEST(CollectivePreconditioner, ASetUpThatSucceedsEverywhereIsTheInnerOnes) {
  const auto inner = Teuchos::rcp(new FakePreconditioner(false));
  const auto factory = collectivePreconditioner(inner);
  const auto prec = factory->createPrec();
  EXPECT_NO_THROW(factory->initializePrec(identitySource(), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED));
  EXPECT_EQ(inner->setups, 1);
  EXPECT_FALSE(prec->getUnspecifiedPrecOp().is_null());
}

TEST(CollectivePreconditioner, TheRunsLinearSolversPreconditionerIsCollective) {
  LinearSolverParameters section;
  section.type = LinearSolverType::iterative;
  LinearSolverContext context;
  context.ranks = Tpetra::getDefaultComm()->getSize();
  context.globalRows = 4 * context.ranks;
  for (const Preconditioner p : {Preconditioner::mueLu, Preconditioner::ifpack2}) {
    section.preconditioner = p;
    const auto solver = buildLinearSolver(section, context);
    ASSERT_FALSE(solver->getPreconditionerFactory().is_null());
    EXPECT_EQ(solver->getPreconditionerFactory()->description().rfind("collective ", 0), 0u);
  }
  section.preconditioner = Preconditioner::mueLu;
  EXPECT_EQ(buildDisplacementPreconditioner(section, context)->description().rfind("collective ", 0), 0u);
}
