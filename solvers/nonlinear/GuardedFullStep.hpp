#pragma once
// Newton's full step, halved while it leaves an invalid state: an element turned inside out at a
// Gauss point or a muscle point law failing, which the model evaluator reports as a non-finite
// residual (`Nonlinear solver/line search = guarded full step`, doc/incompressibility.md).
//
// Unlike NOX's Backtrack it asks nothing of ||f||: a valid full step is taken even where the
// residual grows, as Newton's full step does. Backtrack shortens those too: on the medium tongue's
// GA it took 9.4 Newton iterations per candidate against 7.5, and had not finished the second
// control step after 5 minutes, which the full step took in 1.5.
// With "full step" one inverted trial state fails the whole solve, and the load step is cut back.
//
// Included by NewtonSolver.cpp alone (the NOX headers are heavy).

#include <NOX_Abstract_Group.H>
#include <NOX_LineSearch_Generic.H>
#include <NOX_LineSearch_UserDefinedFactory.H>
#include <NOX_Solver_Generic.H>

#include <cmath>

namespace glossa::solvers {

class GuardedFullStep : public NOX::LineSearch::Generic {
 public:
  // At most `halvings` halvings: the shortest step tried is 2^-halvings.
  explicit GuardedFullStep(int halvings, int &halved) : halvings_(halvings), halved_(halved) {}

  bool compute(NOX::Abstract::Group &group, double &step, const NOX::Abstract::Vector &direction,
               const NOX::Solver::Generic &solver) override {
    const NOX::Abstract::Group &previous = solver.getPreviousSolutionGroup();
    step = 1.0;
    for (int k = 0;; ++k) {
      group.computeX(previous, direction, step);
      group.computeF();
      if (std::isfinite(group.getNormF())) return true;
      if (k == halvings_) break;
      step *= 0.5;
      ++halved_;
    }
    step = 0.0;  // NOX then fails the solve: the state is still invalid at the shortest step
    return false;
  }

 private:
  int halvings_;
  int &halved_;
};

class GuardedFullStepFactory : public NOX::LineSearch::UserDefinedFactory {
 public:
  GuardedFullStepFactory(int halvings, int &halved) : halvings_(halvings), halved_(halved) {}
  Teuchos::RCP<NOX::LineSearch::Generic> buildLineSearch(const Teuchos::RCP<NOX::GlobalData> &,
                                                         Teuchos::ParameterList &) const override {
    return Teuchos::rcp(new GuardedFullStep(halvings_, halved_));
  }

 private:
  int halvings_;
  int &halved_;
};

}  // namespace glossa::solvers
