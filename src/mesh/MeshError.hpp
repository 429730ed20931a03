#pragma once
// A mesh file (or a reference coordinates file) that cannot be read as a valid mesh: its message
// names the file, the line where it can and what is wrong. A bad input like a bad deck
// (`glossa` exits 2), where other runtime errors are Glossa's own.

#include <stdexcept>

namespace glossa::mesh {

class MeshError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace glossa::mesh
