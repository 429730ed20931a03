#pragma once
// A checkpoint that cannot be trusted (glossa run --restart): damaged, cut short, not a Glossa
// checkpoint, or holding values no run could have written. It is a bad input like a bad deck,
// so `glossa` exits 2, its message naming the file and what is wrong.

#include "io/deck/DeckError.hpp"

namespace glossa::io {

class CheckpointError : public DeckError {
public:
  using DeckError::DeckError;
};

} // namespace glossa::io
