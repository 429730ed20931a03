#pragma once
// The Simulation facade (DESIGN.md §3): from a validated deck it builds the scene, the
// distributed assembly, the linear and nonlinear solvers and the Uzawa loop, then steps through
// time, committing each converged step (displacement and multipliers) and rolling back a failed
// one, and writes results as it goes so a run stopped at any point leaves readable files.

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include "io/deck/Deck.hpp"

namespace glossa::solvers {

// Parameters of the sections the solver side owns ("Time", "Incompressibility",
// "Nonlinear solver", "Linear solver", "Output"), to be merged into the deck schema.
void declareSolverParameters(Teuchos::ParameterList &schema);

struct RunOptions {
  std::filesystem::path outputDirectory; // empty: the deck's Output/directory
  bool quiet = false;
  // The ranks split into this many groups, each solving GA candidates on its own
  // sub-communicator (issue 5); must divide the rank count. 1: every rank solves every candidate.
  int controlGroups = 1;
  // If set, receives the last converged displacement of every node (3 per node, by mesh node),
  // on every rank (glossa zero-strain).
  std::vector<double> *finalDisplacement = nullptr;
};

// Runs the deck; returns the summary that was written to summary.json. Collective.
// Throws io::DeckError for deck problems found while building the scene.
nlohmann::json runSimulation(const io::Deck &deck, const Teuchos::RCP<const Teuchos::Comm<int>> &comm,
                             const RunOptions &options);

} // namespace glossa::solvers
