#include "input/UnreadParameters.hpp"

#include <algorithm>

#include "input/DeckSets.hpp"
#include "io/deck/DeckError.hpp"

namespace glossa::input {

void refuseUnreadParameters(const io::Deck &deck, const std::vector<std::string> &path, const std::string &selector,
                            const std::vector<ReadUnder> &readers) {
  auto at = [&](const std::string &name) {
    auto where = path;
    where.push_back(name);
    return where;
  };
  const std::string &chosen = deckString(deck, at(selector));
  // A choice changed by --set leaves the file's parameters of the old choice behind on purpose
  // (a deck's constant direction field tried as a radial fan): only what --set adds is refused.
  const bool choiceSet = deck.setOnCommandLine(at(selector));
  for (const ReadUnder &r : readers) {
    if (!deck.given(at(r.parameter)) || std::find(r.words.begin(), r.words.end(), chosen) != r.words.end()) continue;
    if (choiceSet && !deck.setOnCommandLine(at(r.parameter))) continue;
    std::string readers;
    for (const auto &w : r.words) readers += (readers.empty() ? "" : ", ") + w;
    throw io::DeckError(deck.where(at(r.parameter)) + " is not read when '" + selector + "' is " + chosen +
                        " (only with " + readers + "), so its value would be ignored; remove it or change '" +
                        selector + "'");
  }
}

} // namespace glossa::input
