#pragma once
// Random warped faces for the contact kernels' finite-difference tests.

#include <random>

#include "loads/DeadTraction.hpp"

namespace glossa::test {

// X with each coordinate moved by up to `size`, uniformly at random.
inline loads::FaceNodes perturbed(const loads::FaceNodes &X, std::mt19937 &rng, double size) {
  std::uniform_real_distribution<double> d(-size, size);
  loads::FaceNodes Y = X;
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) Y(a, i) += d(rng);
  return Y;
}

}  // namespace glossa::test
