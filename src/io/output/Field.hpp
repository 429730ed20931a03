#pragma once
// A named field of n values with 1 (scalar), 3 (vector), 6 (symmetric tensor: xx, yy, zz, xy,
// yz, xz) or 9 (tensor) components, stored row-major.

#include <string>
#include <vector>

namespace glossa::io {

struct Field {
  std::string name;
  int components = 1;
  std::vector<double> values; // size n * components
};

} // namespace glossa::io
