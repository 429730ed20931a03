#include "solvers/TimeStepping.hpp"

#include "io/deck/ParameterSpec.hpp"

namespace glossa::solvers {

Teuchos::ParameterList timeParameters() {
  Teuchos::ParameterList p;
  io::declareDouble(p, "end time", 1.0, "s", "time of the last step", io::Range::positive());
  io::declareDouble(p, "step size", 0.1, "s", "nominal step", io::Range::positive());
  io::declareDouble(p, "minimum step size", 1e-6, "s",
                    "the run stops (and says why) when a failing step would be cut below this",
                    io::Range::positive());
  io::declareString(p, "predictor", "none",
                    "where each step's Newton iteration (and every candidate solve of a controlled step) "
                    "starts: none (the last committed state) or linear extrapolation (the last two "
                    "committed states, displacement and multipliers, extrapolated to the new time; the "
                    "same for every candidate, so control groups still agree bit for bit; measured slower "
                    "on the breathing tongue, +10 % Newton iterations, and on the step-44 block, where it "
                    "overshoots into cut-backs: bench/README.md)",
                    {"none", "linear extrapolation"});
  io::declareString(p, "at a limit point", "stop",
                    "stop: after each converged step the tangent's stiffness along the load path is measured "
                    "(one tangent solve; a path driven by activation alone has no load rate and is not "
                    "measured); a state past a limit point (negative stiffness: an unstable "
                    "equilibrium, e.g. the far branch of an inflated sphere) is refused, the step is cut back "
                    "until the limit point is bracketed to the tolerance below, and the run stops naming it "
                    "(summary.json: limit_point); ignore: no measurement, any converged state is accepted "
                    "(the mixed method never measures: doc/theory.md)",
                    {"stop", "ignore"});
  io::declareDouble(p, "limit point tolerance", 0.01, "",
                    "a limit point is located once the bracket's step is below this fraction of the nominal "
                    "step size", io::Range::open(0.0, 1.0));
  return p;
}

StepSizeRule stepSizeRule(const Teuchos::ParameterList &s) {
  return {s.get<double>("end time"), s.get<double>("step size"), s.get<double>("minimum step size")};
}

} // namespace glossa::solvers
