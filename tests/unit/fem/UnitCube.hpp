#pragma once
// The unit cube [0, 1]^3 as a trilinear hexahedron in the node order of fem::hexNodeXi, the
// element the corner and fold tests deform by hand, and random nodal displacements for the
// element tests.

#include <random>

#include "fem/HexShape.hpp"

namespace glossa::fem::testing {

inline NodeMatrix unitCube() {
  NodeMatrix X;
  for (int a = 0; a < 8; ++a) X.row(a) = 0.5 * (hexNodeXi(a).array() + 1.0).matrix().transpose();
  return X;
}

// Every nodal component uniform in [-amplitude, amplitude].
inline NodeMatrix randomNodalDisplacement(std::mt19937 &rng, double amplitude) {
  std::uniform_real_distribution<double> d(-amplitude, amplitude);
  NodeMatrix u;
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) u(a, i) = d(rng);
  return u;
}

} // namespace glossa::fem::testing
