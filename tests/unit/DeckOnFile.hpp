#pragma once
// A deck for unit tests of the parsing layer and its users: XML written to the test's temporary
// directory and validated, so that its errors name a file and a line as a user's deck would.

#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/deck/Deck.hpp"
#include "io/deck/DeckError.hpp"
#include "ProcessScratch.hpp"

namespace glossa::test {

// The file `name` in the test process's temporary directory, as a deck's messages name it.
inline std::string deckPath(const std::string &name) { return (processScratch() / name).string(); }

// `sections`: the XML inside <ParameterList name="Glossa">, which is line 1, so that the first
// line of `sections` is line 2. Validated against `schema` (every default filled in).
inline io::Deck deckOnFile(const std::string &name, const std::string &sections, const Teuchos::ParameterList &schema,
                           const std::vector<std::string> &overrides = {}) {
  std::ofstream(deckPath(name)) << "<ParameterList name=\"Glossa\">\n" << sections << "</ParameterList>\n";
  auto deck = io::Deck::fromFile(deckPath(name));
  for (const auto &o : overrides) deck.applyOverride(o, schema);
  deck.validate(schema);
  return deck;
}

// The message of the io::DeckError that `f` throws; "" if it throws none.
template <class F> std::string deckErrorOf(F &&f) {
  try {
    f();
  } catch (const io::DeckError &e) {
    return e.what();
  }
  return "";
}

} // namespace glossa::test
