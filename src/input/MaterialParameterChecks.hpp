#pragma once
// What a material's deck sections may give together. A tissue (Material, or a sublist of
// Material/Tissues): only the parameters of its own matrix law, and its bulk modulus either
// directly or through Poisson's ratio, not both. A fibre family: only the parameters of its own
// direction field. Every parameter has a default, so a value nothing reads (Fung A on a
// neo-Hookean tissue, nu beside a bulk modulus, a fan centre of a constant direction) would
// otherwise be dropped without a word.

#include <string>
#include <vector>

#include "io/deck/Deck.hpp"

namespace glossa::input {

// Refuses (DeckError at the parameter) a given parameter of another matrix law than `type`'s.
void refuseOtherLawsParameters(const io::Deck &deck, const std::vector<std::string> &path);

// Refuses a given parameter of another direction field than the family's 'direction field'.
void refuseOtherFieldsParameters(const io::Deck &deck, const std::vector<std::string> &path);

// Whether the tissue at `path` takes its bulk modulus from 'bulk modulus' (true) or from
// "Poisson's ratio" (false). A bulk modulus > 0 and Poisson's ratio both in the file, or both set
// on the command line, are refused naming both; one set on the command line over the other in
// the file replaces it (a sweep over kappa on a deck that gives nu).
bool bulkModulusGiven(const io::Deck &deck, const std::vector<std::string> &path);

} // namespace glossa::input
