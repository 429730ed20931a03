#include "solvers/stepping/PathStiffness.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "solvers/linear/LinearSolveFailure.hpp"
#include "solvers/nonlinear/NewtonSolver.hpp"

namespace glossa::solvers {

namespace {
// The monitor asks the sign of S and whether it is below 0.1: three digits are plenty. CG's iterate
// is the K-orthogonal projection of the answer, so w^T df/dt is even second order in its error.
// At the deck's 1e-6, and with a preconditioner of its own, the solve took a quarter of the
// step-44 block's run at 16 per side (doc/theory.md).
constexpr double kTangentTolerance = 1e-3;
} // namespace

PathStiffness pathStiffness(const assembly::Assembler &assembler, const NewtonSolver &newton, const assembly::Vector &u,
                            double time, double dt, const std::vector<double> &lambda, bool ownSolver) {
  PathStiffness out{std::numeric_limits<double>::quiet_NaN(), 0, {}};
  // df/dt at fixed u: the loads and the prescribed displacements at t -+ h. h small against the
  // step (a tabulated load is linear between its rows), large against round-off.
  const double h = 1e-4 * dt;
  assembly::Vector later(u, Teuchos::Copy), earlier(u, Teuchos::Copy), fLater(u.getMap()), fEarlier(u.getMap());
  assembler.applyDirichlet(later, time + h);
  assembler.applyDirichlet(earlier, time - h);
  assembly::Vector moved(later, Teuchos::Copy);
  moved.update(-1.0, earlier, 1.0);
  double scale = 0.0;
  if (moved.normInf() == 0.0) {
    // No prescribed motion: the element terms at t -+ h are the same numbers and cancel; the
    // loads alone carry df/dt (two passes over the point laws saved per step).
    fLater = assembler.loadResidual(later, time + h);
    fEarlier = assembler.loadResidual(earlier, time - h);
    scale = std::max(fLater.norm2(), fEarlier.norm2());
  } else {
    const auto status = assembler.assemble(later, time + h, lambda, nullptr, &fLater, nullptr);
    if (!status.valid || !assembler.assemble(earlier, time - h, lambda, nullptr, &fEarlier, nullptr).valid) {
      out.note = "a state a little along the path is inverted";
      return out;
    }
    scale = status.forceScale;
  }
  fLater.update(-1.0, fEarlier, 1.0); // 2h df/dt
  // Loads that do not change with time (gravity held, activation only) give exactly zero here.
  if (!(fLater.norm2() > 1e-13 * scale)) return out;
  assembly::Vector rhs(u.getMap()), w(u.getMap()); // w: 2h du/dt
  rhs.update(-1.0, fLater, 0.0);
  try {
    if (ownSolver) {
      assembly::MultiVector b(u.getMap(), 1), x(u.getMap(), 1);
      b.getVectorNonConst(0)->assign(rhs);
      out.krylovIterations = newton.solveTangent(u, b, x, kTangentTolerance);
      w.assign(*x.getVector(0));
    } else {
      out.krylovIterations = newton.solveTangentWithKeptSolver(u, rhs, w, kTangentTolerance);
    }
  } catch (const std::exception &e) {
    // CG's p^T K p <= 0 is itself a direction along which K is not positive definite.
    out.note = linearSolveFailure(e.what());
    if (out.note.find("negative curvature") != std::string::npos) out.stiffness = -std::numeric_limits<double>::infinity();
    return out;
  }
  assembly::Vector free(w, Teuchos::Copy);
  assembler.zeroConstrainedDofs(free);
  const double ww = free.dot(free);
  if (!(ww > 0.0)) return out;
  // w^T K w = -w^T (2h df/dt) over the free dofs (K's constrained rows are the identity's).
  out.stiffness = -free.dot(fLater) / ww;
  return out;
}

} // namespace glossa::solvers
