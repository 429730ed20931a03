#pragma once
// A preconditioner factory whose set-up fails on every rank or on none. MueLu gathers its coarse
// levels onto one rank (LinearSolverFactory: repartitioning), so a smoother there can fail on
// that rank alone (Ifpack2's Chebyshev meeting a NaN in its eigenvalue estimate): that rank
// unwound to the step's cut-back while the other went on into the Krylov solve, and the job died
// in MPI_Allreduce with MPI_ERR_TRUNCATE. Wrapped, the set-up's exception is caught on the rank
// that threw, the ranks agree once the set-up is over (assembly/RankAgreement), and every rank
// throws the same std::runtime_error: "preconditioner set-up failed on rank R of N: <reason>".
// A failure inside a collective call of the wrapped set-up that other ranks are still in cannot be
// mended this way; the coarse levels' set-up, on one rank, is not one.

#include <Thyra_LinearOpWithSolveFactoryBase.hpp>
#include <Thyra_PreconditionerFactoryBase.hpp>

namespace glossa::solvers {

Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>>
collectivePreconditioner(const Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> &inner);

// Replaces the preconditioner factory of `solver` (if it has one) by its collective wrapper.
void makePreconditionerCollective(Thyra::LinearOpWithSolveFactoryBase<double> &solver);

} // namespace glossa::solvers
