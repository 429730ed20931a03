#pragma once
// The deck's solver-side sections (Time, Incompressibility, Nonlinear solver, Linear solver,
// Output, Control), parsed once into their typed structs and handed on: the run's parts read
// these, never the deck. The identity of the deck a restart must be given travels with them.

#include <string>
#include <vector>

#include "solvers/parameters/IncompressibilityParameters.hpp"
#include "solvers/parameters/LinearSolverParameters.hpp"
#include "solvers/parameters/NewtonParameters.hpp"
#include "solvers/parameters/OutputParameters.hpp"
#include "solvers/parameters/TimeParameters.hpp"

namespace glossa::io {
class Deck;
}

namespace glossa::solvers {

struct RunConfiguration {
  std::string deckFile;
  TimeParameters time;
  IncompressibilityParameters incompressibility;
  NewtonParameters newton;
  LinearSolverParameters linear;
  OutputParameters output;
  bool controlled = false; // Control/type is not none
  // The deck as "Section/sub/name = value" lines, every default filled in and doubles to 17
  // digits: a restart must be given the same.
  std::string listing;
  // Linear solver parameters the deck gives that only the iterative solver uses, each as
  // "file:line: Linear solver/name" (Deck::where), so that a direct solve can say they are unused.
  std::vector<std::string> givenIterativeOnly;
};

// Parameters of the sections the solver side owns ("Time", "Incompressibility",
// "Nonlinear solver", "Linear solver", "Output", "Control"), to be merged into the deck schema.
void declareSolverParameters(Teuchos::ParameterList &schema);

// `deck`: validated (every default filled in).
RunConfiguration parseRunConfiguration(const io::Deck &deck);

// The first parameter where two listings differ ("" if none), for the message that a restart's
// deck is not the run's.
std::string firstListingDifference(const std::string &run, const std::string &now);

} // namespace glossa::solvers
