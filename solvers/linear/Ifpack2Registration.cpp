#include "assembly/TpetraTypes.hpp"

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>
#include <Thyra_Ifpack2PreconditionerFactory.hpp>

#include "solvers/linear/PreconditionerRegistration.hpp"

namespace glossa::solvers {

void registerIfpack2(Stratimikos::DefaultLinearSolverBuilder &builder) {
  using Base = Thyra::PreconditionerFactoryBase<double>;
  using Impl = Thyra::Ifpack2PreconditionerFactory<assembly::CrsMatrix>;
  builder.setPreconditioningStrategyFactory(Teuchos::abstractFactoryStd<Base, Impl>(), "Ifpack2");
}

} // namespace glossa::solvers
