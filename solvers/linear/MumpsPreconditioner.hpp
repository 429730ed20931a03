#pragma once
// A sparse direct factorisation of the tangent (MUMPS, the multifrontal solver Debian ships with
// Trilinos; MPI-parallel) offered to Stratimikos as a preconditioner, "MUMPS". Inside the Krylov
// solver it is an exact inverse: CG or GMRES stop after one iteration, and the Krylov method's own
// residual check still stands behind the answer. Below some thousands of unknowns this beats any
// multigrid set-up (doc/incompressibility.md, "Direct solves"), and it does not care how close
// to incompressible the tangent is.
//
// The analysis (ordering and symbolic factorisation) is done once per sparsity pattern and kept
// by the factory for the whole run: every Newton iteration and load step refactors numerically
// only. The entries go to MUMPS as each rank's owned rows (distributed assembled input); the
// right-hand side and the solution pass through rank 0. "gathered" on several ranks: MUMPS runs
// on rank 0 alone, the other ranks sending it their rows' entries, so the answer is the same bit
// for bit from run to run (a factorisation shared among ranks is scheduled dynamically and its
// last bits vary); for the small problems `type = auto` solves directly the factorisation is
// cheap beside the assembly the ranks still share.
//
// "reuse iterations" k > 0 keeps a factorisation through the Newton iterations of one Newton
// solve (a stale factor of a nearby tangent is a very good preconditioner): it is refactored at
// the first linear solve of every Newton solve (beginNewtonSolve) and whenever the previous
// solve took more than k Krylov iterations. So the sequence of factorisations is a function of
// the Newton solve alone, and a restarted run repeats it. "reuse scope" = step keeps it across the
// Newton solves (Uzawa iterations) of a step, refactored when a step begins (beginStep), so a
// restarted run still repeats it; run keeps it across steps (a restart then differs within the
// solver tolerances).

#include <memory>

#include <Thyra_PreconditionerFactoryBase.hpp>

#include "assembly/TpetraTypes.hpp"

namespace glossa::solvers {

class MumpsFactorization;

class MumpsPreconditionerFactory : public Thyra::PreconditionerFactoryBase<double> {
public:
  MumpsPreconditionerFactory();
  ~MumpsPreconditionerFactory() override;

  bool isCompatible(const Thyra::LinearOpSourceBase<double> &fwdOpSrc) const override;
  Teuchos::RCP<Thyra::PreconditionerBase<double>> createPrec() const override;
  void initializePrec(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> &fwdOpSrc,
                      Thyra::PreconditionerBase<double> *prec, const Thyra::ESupportSolveUse supportSolveUse) const override;
  void uninitializePrec(Thyra::PreconditionerBase<double> *prec,
                        Teuchos::RCP<const Thyra::LinearOpSourceBase<double>> *fwdOpSrc,
                        Thyra::ESupportSolveUse *supportSolveUse) const override;

  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList> &paramList) override;
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override { return params_; }
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override;
  Teuchos::RCP<const Teuchos::ParameterList> getParameterList() const override { return params_; }
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override;

  // A Newton solve begins: with reuse within a Newton solve, the next preconditioner is a fresh
  // factorisation.
  static void beginNewtonSolve();
  // A step (a candidate's solve, a point of a path) begins: the next preconditioner is a fresh
  // factorisation, unless factors are kept for the run.
  static void beginStep();

private:
  Teuchos::RCP<Teuchos::ParameterList> params_;
  // Shared by every preconditioner this factory made: a stale one still preconditions, and the
  // analysis outlives the Newton solves.
  mutable std::shared_ptr<MumpsFactorization> factorization_;
};

} // namespace glossa::solvers
