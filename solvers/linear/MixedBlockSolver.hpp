#pragma once
// The linear solve of Incompressibility/method = mixed (doc/incompressibility.md): NOX hands it the
// model evaluator's blocked tangent over [u; p~] (assembly::MixedPressureState),
//   [ K  B^T ] [du ]   [ b_u ]
//   [ B  -C  ] [dp~] = [ b_p ],
// and it returns both parts. Belos GMRES (the system is symmetric indefinite) with Teko's block
// upper-triangular preconditioner
//   P = [ K_hat  B^T ; 0  -S_hat ],   K_hat^{-1}: the deck's preconditioner of K (MueLu by
//   default), S_hat = C + M_p / mu: the Schur complement B K^{-1} B^T + C with K^{-1} replaced by
//   (mu times the P0 mass matrix M_p = diag(V_e))^{-1}, exact in its C part (kappa = inf: C = 0).
// The Krylov tolerance is relative to the norm of the whole right-hand side.

#include <Teuchos_ParameterList.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

#include "assembly/MixedPressureState.hpp"
#include "solvers/linear/LinearSolverFactory.hpp"

namespace glossa::solvers {

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>>
buildMixedBlockSolver(const LinearSolverParameters &linearSection, const LinearSolverContext &context,
                      Teuchos::RCP<assembly::MixedPressureState> state);

} // namespace glossa::solvers
