#pragma once
// A file a deck names, relative to the deck's own folder unless absolute.

#include <filesystem>
#include <string>

#include "io/deck/Deck.hpp"

namespace glossa::input {

inline std::string relativeToDeck(const io::Deck &deck, const std::string &path) {
  const std::filesystem::path q(path);
  return (q.is_relative() ? std::filesystem::path(deck.file()).parent_path() / q : q).string();
}

}  // namespace glossa::input
