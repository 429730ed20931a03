#pragma once
// The unit cube [0, 1]^3 as a trilinear hexahedron in the node order of fem::hexNodeXi, the
// element the corner and fold tests deform by hand.

#include "fem/HexShape.hpp"

namespace glossa::fem::testing {

inline NodeMatrix unitCube() {
  NodeMatrix X;
  for (int a = 0; a < 8; ++a) X.row(a) = 0.5 * (hexNodeXi(a).array() + 1.0).matrix().transpose();
  return X;
}

} // namespace glossa::fem::testing
