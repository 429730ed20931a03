#include "assembly/TpetraTypes.hpp"

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>
#include <Thyra_MueLuPreconditionerFactory_decl.hpp>

#include "solvers/linear/PreconditionerRegistration.hpp"

// MueLu is built with explicit instantiation, and its adapters library holds the Thyra factory for
// exactly these types: declaring the instantiation extern uses that one instead of instantiating
// the factory's definitions (and through them MueLu's hierarchy set-up) here again. This is what
// Stratimikos::enableMueLu registers, without its header, which includes the definitions: the
// unit compiled in 18 s instead of 48 s.
extern template class Thyra::MueLuPreconditionerFactory<double, glossa::assembly::LO, glossa::assembly::GO,
                                                        glossa::assembly::Node>;

namespace glossa::solvers {

void registerMueLu(Stratimikos::DefaultLinearSolverBuilder &builder) {
  using Base = Thyra::PreconditionerFactoryBase<double>;
  using Impl = Thyra::MueLuPreconditionerFactory<double, assembly::LO, assembly::GO, assembly::Node>;
  builder.setPreconditioningStrategyFactory(Teuchos::abstractFactoryStd<Base, Impl>(), "MueLu");
}

} // namespace glossa::solvers
