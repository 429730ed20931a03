// RandomStream: the distributions written out over std::mt19937_64 (so that a seed gives the
// same run with any standard library): ranges, uniformity of index(), the normal's moments.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "control/RandomStream.hpp"

namespace glossa::control {
namespace {

TEST(RandomStream, IsTheMersenneTwisterStream) {
  // uniform() is the top 53 bits of the engine's draw: the 10000th draw of the default-seeded
  // mt19937_64 is fixed by the C++ standard (9981545732273789042).
  RandomStream r(5489u);
  for (int i = 0; i < 9999; ++i) r.uniform();
  EXPECT_EQ(r.uniform(), static_cast<double>(9981545732273789042ull >> 11) * 0x1.0p-53);
}

TEST(RandomStream, RangesAndUniformity) {
  RandomStream r(3);
  const int draws = 60000;
  std::vector<int> counts(6, 0);
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < draws; ++i) {
    const double u = r.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    const auto k = r.index(6);
    ASSERT_LT(k, 6u);
    ++counts[k];
    const double z = r.normal();
    sum += z;
    sum2 += z * z;
  }
  // Each face of a die: 10000 expected, standard deviation ~91; 5 sigma.
  for (int c : counts) EXPECT_NEAR(c, draws / 6, 460);
  EXPECT_NEAR(sum / draws, 0.0, 5.0 / std::sqrt(draws));
  EXPECT_NEAR(sum2 / draws, 1.0, 5.0 * std::sqrt(2.0 / draws));
  EXPECT_EQ(r.index(1), 0u);
}

}  // namespace
}  // namespace glossa::control
