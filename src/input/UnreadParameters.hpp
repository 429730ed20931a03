#pragma once
// Parameters a deck gives that the choice beside them would not read: `Fung A` on a neo-Hookean
// tissue, a `fan centre` under a constant direction field, a `ramp duration` of a table. Every
// parameter has a default, so such a value would be dropped without a word and the run would
// not be the one the author wrote; it is refused instead, naming the parameter, the choice and
// what would read it.

#include <string>
#include <vector>

#include "io/deck/Deck.hpp"

namespace glossa::input {

// A parameter and the words of the selector under which it is read.
struct ReadUnder {
  std::string parameter;
  std::vector<std::string> words;
};

// For the section at `path`, whose string parameter `selector` chooses what is read: a parameter
// of `readers` that the user gave (io::Deck::given) while the selector's word is not among its
// words is a DeckError at that parameter; when --set gave the selector, only if --set gave the
// parameter too (the deck file's parameters of the choice --set replaced are left unread).
void refuseUnreadParameters(const io::Deck &deck, const std::vector<std::string> &path, const std::string &selector,
                            const std::vector<ReadUnder> &readers);

} // namespace glossa::input
