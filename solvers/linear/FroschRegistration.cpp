#include "assembly/TpetraTypes.hpp"

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Stratimikos_FROSch_def.hpp>

#include "solvers/linear/PreconditionerRegistration.hpp"

namespace glossa::solvers {

// FROSch ships no instantiations (its library exports none of Thyra::FROSchFactory's members), so
// this unit instantiates all of it: the heaviest unit of the build.
void registerFrosch(Stratimikos::DefaultLinearSolverBuilder &builder) {
  Stratimikos::enableFROSch<assembly::LO, assembly::GO, assembly::Node>(builder);
}

} // namespace glossa::solvers
