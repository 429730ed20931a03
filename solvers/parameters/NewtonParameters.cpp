#include "solvers/parameters/NewtonParameters.hpp"

#include "io/deck/ParameterSpec.hpp"

namespace glossa::solvers {

Teuchos::ParameterList nonlinearSolverParameters() {
  Teuchos::ParameterList p;
  io::declareInt(p, "maximum iterations", 25, "Newton iterations per solve before the step is cut back",
                 io::Range::closed(1, 1000));
  io::declareDouble(p, "residual tolerance", 1e-8, "",
                    "converged when ||f|| <= this x max(||f_ext||, ||f|| at the start of the step); "
                    "round-off puts a floor near 1e-10 of the load when kappa/mu is in the thousands",
                    io::Range::open(0.0, 1.0));
  io::declareDouble(p, "update tolerance", 1e-6, "",
                    "and when the Newton update is below this relative to the whole field "
                    "(2-norms; absolute floor 1e-9 of the mesh size per unknown); the update lags an "
                    "iteration behind, so with Newton's quadratic convergence 1e-6 leaves an error far "
                    "below it (1e-8 gave the same answers to 1e-15 with an extra iteration per solve: "
                    "doc/incompressibility.md)",
                    io::Range::open(0.0, 1.0));
  io::declareString(p, "forcing term", "Type 2",
                    "linear tolerance per Newton iteration: constant (the Linear solver tolerance), "
                    "Eisenstat-Walker 'Type 1' (NOX's) or 'Type 2' (loose while far from the "
                    "solution, down to the Linear solver tolerance, and never below half the "
                    "residual tolerance over the residual: the last iteration of a solve asks only "
                    "what the residual test needs; doc/incompressibility.md)",
                    {"constant", "Type 1", "Type 2"});
  io::declareString(p, "line search", "full step",
                    "full step (Newton's; a trial state with an element turned inside out or a muscle "
                    "point law failing fails the solve, and the load step is cut back), guarded full step "
                    "(the full step, halved up to 4 times while its state is invalid; no test of the "
                    "residual's norm), or NOX's backtrack or polynomial (halved or fitted until the "
                    "residual's norm decreases): doc/incompressibility.md, \"Newton's line search\"",
                    {"full step", "guarded full step", "backtrack", "polynomial"});
  return p;
}

NewtonParameters parseNewtonParameters(const Teuchos::ParameterList &s) {
  NewtonParameters p;
  p.maximumIterations = s.get<int>("maximum iterations");
  p.residualTolerance = s.get<double>("residual tolerance");
  p.updateTolerance = s.get<double>("update tolerance");
  const std::string forcing = s.get<std::string>("forcing term");
  p.forcing = forcing == "constant" ? ForcingTerm::constant : forcing == "Type 1" ? ForcingTerm::type1 : ForcingTerm::type2;
  const std::string ls = s.get<std::string>("line search");
  p.lineSearch = ls == "backtrack"           ? LineSearch::backtrack
                 : ls == "polynomial"        ? LineSearch::polynomial
                 : ls == "guarded full step" ? LineSearch::guardedFullStep
                                             : LineSearch::fullStep;
  return p;
}

} // namespace glossa::solvers
