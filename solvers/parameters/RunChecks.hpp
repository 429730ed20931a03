#pragma once
// The checks that need more than one deck section and the scene built from it, the same for
// glossa validate and glossa run: each tissue's law against the method, the mixed method's and
// arc-length continuation's requirements, the output's face sets, the control
// groups' count, and the iterative-solver settings a direct solve leaves unused. Run before the
// output directory is touched, so a bad deck leaves an earlier run's files intact.

#include <string>
#include <vector>

#include "solvers/parameters/RunConfiguration.hpp"

namespace glossa::model {
struct Scene;
}

namespace glossa::solvers {

struct ControlSetup;

// What the command line adds to the deck for these checks.
struct RunCheckContext {
  int ranks = 1;
  int controlGroups = 1;    // --control-groups
  bool restart = false;     // --restart
};

// Throws io::DeckError, naming the parameter, for the first combination a run cannot make.
void checkRunConfiguration(const io::Deck &deck, const RunConfiguration &config, const model::Scene &scene,
                           const ControlSetup &control, const RunCheckContext &context);
// `--control-groups G` alone (before the scene is built): G must divide the rank count.
void checkControlGroupCount(int controlGroups, int ranks);

// Linear solver/type = auto solved directly (a small problem): the settings the deck
// gives for the iterative solver, each named as a warning (empty when the solve is iterative).
std::vector<std::string> ignoredIterativeSettings(const RunConfiguration &config, bool direct, long long unknowns);

} // namespace glossa::solvers
