#pragma once
// A run of a validated deck from start to end, as `glossa run` makes it: what its callers (the
// command, glossa zero-strain, the integration tests) need, without the Simulation's parts. The
// Simulation's header carries Tpetra's vectors and the Assembler, Kokkos with them; this one only
// Teuchos' communicator (test_step44_block.cpp, cold: 13.1 s and 685 MB with the Simulation's
// header, 8.6 s and 464 MB with this one).

#include <nlohmann/json.hpp>
#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "io/deck/Deck.hpp"
#include "solvers/parameters/RunConfiguration.hpp"
#include "solvers/run/RunOptions.hpp"

namespace glossa::solvers {

// Runs the deck with its solver sections `config` (parseRunConfiguration); returns the summary
// that was written to summary.json. Collective. Throws io::DeckError for deck problems found
// while building the scene.
nlohmann::json runSimulation(const io::Deck &deck, const RunConfiguration &config,
                             const Teuchos::RCP<const Teuchos::Comm<int>> &comm, const RunOptions &options);

} // namespace glossa::solvers
