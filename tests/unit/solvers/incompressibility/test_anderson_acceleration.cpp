// Anderson acceleration of the multiplier update (solvers/incompressibility/AndersonAcceleration):
// on an affine contraction with a few distinct rates, as the Uzawa update is near convergence, it
// removes each rate in about one update, where the plain iteration needs hundreds.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "solvers/incompressibility/AndersonAcceleration.hpp"

using glossa::solvers::AndersonAcceleration;

namespace {
// G(x) = x* + A (x - x*), A diagonal with the rates 0.9, 0.5 and 0.1 over 12 entries: the slow
// mode of active fibres beside the fast ones of passive tissue.
struct AffineContraction {
  std::vector<double> fixedPoint, rates;
  AffineContraction() {
    for (int i = 0; i < 12; ++i) {
      fixedPoint.push_back(std::sin(1.0 + i));
      rates.push_back(i % 3 == 0 ? 0.9 : i % 3 == 1 ? 0.5 : 0.1);
    }
  }
  std::vector<double> operator()(const std::vector<double> &x) const {
    std::vector<double> g(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) g[i] = fixedPoint[i] + rates[i] * (x[i] - fixedPoint[i]);
    return g;
  }
  double error(const std::vector<double> &x) const {
    double e = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) e = std::max(e, std::abs(x[i] - fixedPoint[i]));
    return e;
  }
};

int updatesTo(double tolerance, const AffineContraction &map, AndersonAcceleration *anderson) {
  std::vector<double> x(map.fixedPoint.size(), 0.0);
  for (int k = 1; k <= 1000; ++k) {
    x = anderson ? anderson->next(x, map(x)) : map(x);
    if (map.error(x) < tolerance) return k;
  }
  return 1001;
}
} // namespace

TEST(AndersonAcceleration, RemovesThreeRatesInAFewUpdatesWherePlainUzawaNeedsHundreds) {
  const AffineContraction map;
  AndersonAcceleration anderson(3);
  const int accelerated = updatesTo(1e-10, map, &anderson);
  const int plain = updatesTo(1e-10, map, nullptr);
  // Plain: the slow rate alone needs log(1e-10 / 1) / log(0.9) = 219 updates.
  EXPECT_GE(plain, 200);
  // A multisecant method on three distinct rates: the first update plain, then one per rate, and
  // one more for round-off.
  EXPECT_LE(accelerated, 6) << "plain took " << plain;
}

TEST(AndersonAcceleration, FirstUpdateAfterAResetIsThePlainOne) {
  const AffineContraction map;
  AndersonAcceleration anderson(2);
  std::vector<double> x(12, 0.0);
  EXPECT_EQ(anderson.next(x, map(x)), map(x));
  x = map(x);
  (void)anderson.next(x, map(x));
  EXPECT_EQ(anderson.pairs(), 1);
  anderson.reset();
  EXPECT_EQ(anderson.pairs(), 0);
  EXPECT_EQ(anderson.next(x, map(x)), map(x));
}

TEST(AndersonAcceleration, KeepsAtMostItsDepthOfPairs) {
  const AffineContraction map;
  AndersonAcceleration anderson(2);
  std::vector<double> x(12, 0.0);
  for (int k = 0; k < 5; ++k) x = anderson.next(x, map(x));
  EXPECT_EQ(anderson.pairs(), 2);
}

// Two ranks holding the same entries sum every inner product twice: gamma, and so the update, is
// the one rank's (the normal equations scale as a whole). A sum that drops the right-hand side
// would change it: the packing of the Gram matrix and the right-hand side is what is checked.
TEST(AndersonAcceleration, SumsTheNormalEquationsOverTheRanks) {
  const AffineContraction map;
  int calls = 0, lastCount = 0;
  AndersonAcceleration alone(3), twice(3, [&](double *v, int count) {
    ++calls;
    lastCount = count;
    for (int i = 0; i < count; ++i) v[i] *= 2.0;
  });
  std::vector<double> x(12, 0.0), y(12, 0.0);
  for (int k = 0; k < 4; ++k) {
    x = alone.next(x, map(x));
    y = twice.next(y, map(y));
  }
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(x[i], y[i], 1e-13);
  EXPECT_EQ(calls, 3);          // one collective call per update that has a history
  EXPECT_EQ(lastCount, 6 + 3);  // a 3 x 3 upper triangle and 3 right-hand sides
}

TEST(AndersonAcceleration, RefusesNoDepthAndMismatchedSizes) {
  EXPECT_THROW(AndersonAcceleration(0), std::invalid_argument);
  AndersonAcceleration anderson(2);
  EXPECT_THROW(anderson.next(std::vector<double>(3, 0.0), std::vector<double>(4, 0.0)), std::invalid_argument);
}
