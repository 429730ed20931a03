#pragma once
// Arc-length continuation of the load path through Trilinos LOCA (Time/path following = arc
// length): the time t, which scales every load, becomes an unknown beside the displacement, and
// each step solves f(u, t) = 0 together with the arc-length constraint (LOCA's pseudo arc length:
// the step's projection on the path tangent is the step size). Unlike load control it passes a
// load maximum and follows the falling branch (doc/theory.md, "Arc-length continuation").
// LOCA's Stepper runs the path: tangent predictor, Newton corrector on the bordered system
// (NOX, the model's tangent solved by the deck's linear solver), adaptive step size.

#include <functional>
#include <string>

#include <Teuchos_RCP.hpp>

#include "assembly/ModelEvaluator.hpp"

namespace glossa::solvers {

struct ArcLengthSettings {
  double startTime = 0.0;   // the path starts at the committed state, at this time
  double endTime = 1.0;     // the load may not pass its end-time value
  double stepSize = 0.1;    // LOCA's initial and largest arc-length step
  double minimumStepSize = 1e-6;
  int maximumSteps = 100;
  int maximumNewtonIterations = 25;
  double residualTolerance = 1e-8; // absolute, on f (the caller scales it by the load)
  double linearTolerance = 1e-8;
  double stopAtDisplacement = 0.0; // the caller's stop (Time/stop at displacement); 0: none
};

// One converged point of the path, as the caller sees it.
struct ArcLengthPoint {
  int step = 0;              // 1, 2, ...
  double time = 0.0;         // the continuation parameter
  int newtonIterations = 0; // of its corrector
};

struct ArcLengthOutcome {
  bool completed = false;    // stopped by the caller, at the end time or back at t = 0
  int steps = 0;
  std::string failure;       // why LOCA stopped otherwise
};

// Called after each converged point with its displacement; returns false to stop the path there.
using ArcLengthCallback = std::function<bool(const ArcLengthPoint &, const assembly::Vector &)>;

// Follows the path from u at settings.startTime (u holds the prescribed values, which must not
// depend on time). Collective. The model's multipliers and its other state stay as set by the caller.
ArcLengthOutcome followPath(const Teuchos::RCP<assembly::ModelEvaluator> &model, const assembly::Vector &u,
                            const ArcLengthSettings &settings, const ArcLengthCallback &onPoint);

} // namespace glossa::solvers
