#pragma once
// An output file that could not be written (a directory that cannot be created or vanished, a
// full disk, an HDF5 failure): `glossa` exits 4, on every rank.

#include <stdexcept>

namespace glossa::io {

class OutputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace glossa::io
