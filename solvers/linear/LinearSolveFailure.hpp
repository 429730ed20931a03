#pragma once
// A failed Krylov solve explained in words. Belos' exceptions reach Glossa wrapped by Thyra's
// TEUCHOS_TEST_FOR_EXCEPTION, whose text starts with a Trilinos source path and line and
// "Throw number = ..." lines that mean nothing to a user; the cut-back reason in the log and in
// summary.json is this instead. Trilinos-free (plain text).

#include <string>

namespace glossa::solvers {

// "CG met negative curvature p^T A p <= 0: the tangent is not positive definite here
// (Belos::PseudoBlockCGIter::iterate(): non-positive value for p^H*A*p encountered!)".
// Known Belos failures are named (negative curvature, an indefinite preconditioner, loss of
// accuracy, an orthogonalisation failure, a LAPACK failure, a breakdown); anything else keeps
// the exception's own message without the source locations.
std::string linearSolveFailure(const std::string &exceptionText);

} // namespace glossa::solvers
