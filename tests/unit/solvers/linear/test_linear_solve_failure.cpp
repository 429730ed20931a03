// A Belos failure as Thyra throws it (Teuchos' frame: source path, throw number, test) becomes a
// reason in words with Belos' own sentence, never a Trilinos source path.
#include <gtest/gtest.h>

#include "solvers/linear/LinearSolveFailure.hpp"

using glossa::solvers::linearSolveFailure;

namespace {
std::string framed(const std::string &belos) {
  return "./packages/stratimikos/adapters/belos/src/Thyra_BelosLinearOpWithSolve_def.hpp:698:\n\n"
         "Throw number = 3\n\nThrow test that evaluated to true: true\n\n" + belos + "\n";
}
} // namespace

TEST(LinearSolveFailure, NamesBelosFailuresWithoutSourcePaths) {
  const std::string curvature =
      linearSolveFailure(framed("/build/trilinos/packages/belos/src/BelosPseudoBlockCGIter.hpp:574:\n\nThrow number = 1\n\n"
                                "Throw test that evaluated to true: SCT::real(pAp[i]) <= zero\n\n"
                                "Belos::PseudoBlockCGIter::iterate(): non-positive value for p^H*A*p encountered!"));
  EXPECT_EQ(curvature, "CG met negative curvature p^T A p <= 0: the tangent is not positive definite here "
                       "(Belos::PseudoBlockCGIter::iterate(): non-positive value for p^H*A*p encountered!)");
  EXPECT_EQ(curvature.find(".hpp"), std::string::npos);
  EXPECT_NE(linearSolveFailure(framed("Belos::PseudoBlockCGIter::iterate(): negative value for r^H*M*r encountered!"))
                .find("the preconditioner is not positive definite"),
            std::string::npos);
  EXPECT_NE(linearSolveFailure(framed("Belos::BlockGmresSolMgr::solve(): loss of accuracy")).find("loss of accuracy in the Krylov"),
            std::string::npos);
  EXPECT_NE(linearSolveFailure(framed("Belos::BlockGmresSolMgrOrthoFailure: Orthogonalization failed"))
                .find("could not be orthogonalised"),
            std::string::npos);
  // Anything else: the message itself, without the frame.
  EXPECT_EQ(linearSolveFailure(framed("MueLu: something unusual happened")), "MueLu: something unusual happened");
  EXPECT_EQ(linearSolveFailure("plain reason"), "plain reason");
  EXPECT_EQ(linearSolveFailure(framed("")), "no reason given");
}
