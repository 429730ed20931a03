#pragma once
// Along the load path by arc-length continuation (ArcLengthContinuation, Trilinos LOCA) from the
// committed state to its end: the whole run (Time/path following = arc length) or its rest once
// load control has located a limit point (at a limit point = follow). Each converged point is
// checked (corners, inside out) and committed as a step.

#include <functional>

namespace glossa::solvers {

struct RunParts;

// `commit`: makes the load stepper's trial (the point) the committed state and records it.
// A failure, a stop signal or the path's end ends it; the summary says which. Collective.
void followArcLength(RunParts &run, const std::function<void()> &commit);

} // namespace glossa::solvers
