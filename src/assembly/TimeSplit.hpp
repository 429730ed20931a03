#pragma once
// Where a run's time goes, beside the assembly the model evaluator times itself: named Teuchos
// timers that the parts of a Newton iteration start and stop, and that the summary reports as
// `time_split` (seconds and calls of each). A timer costs about a tenth of a microsecond a call,
// so only coarse parts are timed (a factorisation, an output step), never a point or an element.

#include <array>
#include <cstddef>
#include <string>

#include <Teuchos_TimeMonitor.hpp>

namespace glossa::assembly {

enum class TimedPart {
  analysis,
  factorisation,
  directSolve,
  threeFieldBases,
  uzawaUpdate,
  muscleHistory,
  stepOutput,
  inputDerivatives, // a controller's df/dalpha and dg/du (the model's DfDp and DgDx)
  tangentSetup,     // a tangent solve outside Newton: its tangent and its fresh preconditioner
  tangentSolve      // that solve's Krylov iterations, all right-hand sides at once
};
inline constexpr std::size_t kTimedParts = 10;

// The summary's key of each part, in the order of TimedPart.
inline const std::array<std::string, kTimedParts> &timedPartNames() {
  static const std::array<std::string, kTimedParts> names{
      "direct_analysis", "direct_factorisation", "direct_solve",       "three_field_bases", "uzawa_update",
      "muscle_history",  "step_output",          "input_derivatives", "tangent_setup",     "tangent_solve"};
  return names;
}

inline Teuchos::RCP<Teuchos::Time> partTimer(TimedPart part) {
  const std::string name = "Glossa: " + timedPartNames()[static_cast<std::size_t>(part)];
  auto timer = Teuchos::TimeMonitor::lookupCounter(name);
  return timer.is_null() ? Teuchos::TimeMonitor::getNewCounter(name) : timer;
}

// Times its scope as one call of `part`.
class PartTimer {
public:
  explicit PartTimer(TimedPart part) : monitor_(*timerOf(part)) {}

private:
  static const Teuchos::RCP<Teuchos::Time> &timerOf(TimedPart part) {
    static std::array<Teuchos::RCP<Teuchos::Time>, kTimedParts> timers;
    auto &t = timers[static_cast<std::size_t>(part)];
    if (t.is_null()) t = partTimer(part);
    return t;
  }
  Teuchos::TimeMonitor monitor_;
};

} // namespace glossa::assembly
