#pragma once
// What the command line adds to a deck for one run (glossa run, glossa zero-strain).

#include <filesystem>
#include <functional>
#include <vector>

namespace glossa::model {
struct Scene;
}

namespace glossa::solvers {

struct RunOptions {
  std::filesystem::path outputDirectory; // empty: the deck's Output/directory
  bool quiet = false;   // nothing but failures on the console
  bool verbose = false; // every Newton and Uzawa iteration and the controller's detail, not only a line per step
  // The ranks split into this many groups, each solving GA candidates on its own
  // sub-communicator; must divide the rank count. 1: every rank solves every candidate.
  int controlGroups = 1;
  // If set, receives the last converged displacement of every node (3 per node, by mesh node),
  // on every rank (glossa zero-strain).
  std::vector<double> *finalDisplacement = nullptr;
  // glossa run --restart DIR: continue the run whose output directory is DIR from its latest
  // checkpoint (the deck must be the one it was started with); empty: a new run.
  std::filesystem::path restartDirectory = {};
  // If set, changes the scene built from the deck before anything else is set up (glossa
  // zero-strain: the reference positions of an iterate, gravity reversed), so that a command
  // driving runs needs no rewritten deck or intermediate file. The deck's checks have run.
  std::function<void(model::Scene &)> adjustScene = {};
};

} // namespace glossa::solvers
