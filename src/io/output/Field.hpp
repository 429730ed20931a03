#pragma once
// A named field of n tuples, stored row-major (tuple i is values[i*components .. i*components+c)).
// components: 1 scalar, 3 vector, 6 symmetric tensor in the order xx, yy, zz, xy, yz, xz (VTK's
// order; ResultWriter writes it as the full tensor), 9 full tensor (row-major 3x3).

#include <string>
#include <vector>

namespace glossa::io {

struct Field {
  std::string name;
  int components = 1;
  std::vector<double> values; // size n * components
};

} // namespace glossa::io
