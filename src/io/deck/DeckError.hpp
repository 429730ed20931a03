#pragma once
// The one error type for a bad deck: its message names the deck file (and line where it can be
// found), the parameter path and what is allowed, so a user can fix the deck without the source.

#include <stdexcept>
#include <string>

namespace glossa::io {

class DeckError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace glossa::io
