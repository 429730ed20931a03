#pragma once
// SIGTERM and SIGINT end a run cleanly instead of killing it mid-write. The handler only records
// the signal and wakes a watcher thread (a write to a pipe is all a handler may safely do); the
// watcher runs the callback the Simulation registered, which writes summary.json at once with
// the reason. That matters under mpiexec: Open MPI forwards the signal to every rank and kills
// them about a second later, long before a step could finish. Without mpiexec the run also stops
// at the next step boundary (Simulation::run asks stopSignal() on every rank). The same signal
// again within 2 s is the same request (`timeout` signals the process and its group); any later
// or other second signal kills the process as before. Trilinos-free.

#include <functional>

namespace glossa::solvers {

// Installs the handlers for SIGTERM and SIGINT (once per process) and starts the watcher.
void installStopSignalHandlers();
// The signal received so far (SIGTERM or SIGINT), or 0.
int stopSignal();
// "SIGTERM", "SIGINT".
const char *signalName(int signal);
// Runs `callback(signal)` on the watcher thread when a signal arrives (replacing any earlier
// callback); an empty function removes it. The callback must lock what it shares.
void onStopSignal(std::function<void(int)> callback);

} // namespace glossa::solvers
