// ElitistGeneticAlgorithm on binary genomes: known optima checked against brute force over all
// 2^n genomes, elitism, determinism of a seed, the corners of generation 0, and the cache.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <stdexcept>
#include <vector>

#include "control/ElitistGeneticAlgorithm.hpp"

namespace glossa::control {
namespace {

using Objective = std::function<double(const Genome &)>;

// An evaluator that records every batch it is given.
struct RecordingEvaluator {
  Objective f;
  std::vector<std::vector<Genome>> batches;
  std::vector<double> all;  // every objective returned, in order

  std::vector<double> operator()(const std::vector<Genome> &batch) {
    batches.push_back(batch);
    std::vector<double> out;
    for (const Genome &g : batch) out.push_back(f(g));
    all.insert(all.end(), out.begin(), out.end());
    return out;
  }
  ElitistGeneticAlgorithm::Evaluator callback() {
    return [this](const std::vector<Genome> &b) { return (*this)(b); };
  }
  std::size_t calls() const {
    std::size_t n = 0;
    for (const auto &b : batches) n += b.size();
    return n;
  }
};

Genome bits(std::size_t n, unsigned code) {
  Genome g(n);
  for (std::size_t i = 0; i < n; ++i) g[i] = (code >> i) & 1u ? 1.0 : 0.0;
  return g;
}

// The brute-force minimum over all 2^n genomes and the genomes attaining it.
std::pair<double, std::vector<Genome>> bruteForce(std::size_t n, const Objective &f) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<Genome> argmin;
  for (unsigned c = 0; c < (1u << n); ++c) {
    const double v = f(bits(n, c));
    if (v < best) {
      best = v;
      argmin = {bits(n, c)};
    } else if (v == best) {
      argmin.push_back(bits(n, c));
    }
  }
  return {best, argmin};
}

// A weighted sum: the best pattern switches on exactly the genes of negative weight. Objectives
// are kept positive, like eq. 25, so that the default objectiveTolerance = 0 never stops a run.
constexpr double kOffset = 20.0;
const std::vector<double> kWeights = {3.0, -2.0, 1.5, -0.5, -4.0, 2.0, -1.0, 0.25, -3.5, 0.75, -0.125, 1.0};
double weightedSum(const Genome &g) {
  double s = 0.0;
  for (std::size_t i = 0; i < g.size(); ++i) s += kWeights[i] * g[i];
  return kOffset + s;
}

// A deceptive trap on two blocks of 4 bits (Deb and Goldberg): in each block with m bits equal
// to a target pattern, the block scores 4 if m = 4 and 3 - m otherwise, so every step towards
// the target looks worse until the block is complete. The target mixes ones and zeros in both
// blocks, so neither all-off, all-on nor a single gene on is optimal. Minimised as 9 - score
// (positive, like eq. 25).
const Genome kTrapTarget = {1, 0, 1, 1, 0, 1, 1, 0};
double deceptiveTrap(const Genome &g) {
  double score = 0.0;
  for (int block = 0; block < 2; ++block) {
    int m = 0;
    for (int i = 4 * block; i < 4 * block + 4; ++i) m += g[i] == kTrapTarget[i];
    score += m == 4 ? 4.0 : 3.0 - m;
  }
  return 9.0 - score;
}

TEST(ElitistGeneticAlgorithmBinary, FindsTheWeightedSumOptimum) {
  GeneticAlgorithmParameters p;
  p.populationSize = 20;
  p.generations = 200;
  p.stagnationGenerations = 30;
  p.seed = 7;
  const std::size_t n = kWeights.size();
  RecordingEvaluator eval{weightedSum};
  const GeneticAlgorithmResult r = ElitistGeneticAlgorithm(p).minimise(n, eval.callback());

  const auto [best, argmin] = bruteForce(n, weightedSum);
  ASSERT_EQ(argmin.size(), 1u);
  EXPECT_EQ(r.best, argmin.front());
  EXPECT_DOUBLE_EQ(r.bestObjective, best);
  EXPECT_DOUBLE_EQ(best, kOffset - 2.0 - 0.5 - 4.0 - 1.0 - 3.5 - 0.125);
  // It did not simply enumerate the 4096 genomes.
  EXPECT_LT(r.evaluations, 4096u / 4);
}

TEST(ElitistGeneticAlgorithmBinary, FindsTheDeceptiveTrapOptimumForSeveralSeeds) {
  const auto [best, argmin] = bruteForce(8, deceptiveTrap);
  ASSERT_EQ(argmin.size(), 1u);
  ASSERT_EQ(argmin.front(), kTrapTarget);
  ASSERT_DOUBLE_EQ(best, 1.0);
  for (std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
    GeneticAlgorithmParameters p;
    p.populationSize = 24;
    p.generations = 100;
    p.mutationRate = 0.15;
    p.stagnationGenerations = 0;
    p.objectiveTolerance = 0.0;
    p.seed = seed;
    RecordingEvaluator eval{deceptiveTrap};
    const GeneticAlgorithmResult r = ElitistGeneticAlgorithm(p).minimise(8, eval.callback());
    EXPECT_EQ(r.best, kTrapTarget) << "seed " << seed;
    EXPECT_DOUBLE_EQ(r.bestObjective, best) << "seed " << seed;
    EXPECT_LE(r.evaluations, 256u);
  }
}

TEST(ElitistGeneticAlgorithmBinary, BestObjectiveNeverIncreasesAndIsTheBestSeenSoFar) {
  GeneticAlgorithmParameters p;
  p.populationSize = 10;
  p.generations = 40;
  p.stagnationGenerations = 0;
  p.mutationRate = 0.3;  // a lively search, so that the incumbent is often challenged
  p.seed = 11;
  RecordingEvaluator eval{deceptiveTrap};
  const GeneticAlgorithmResult r = ElitistGeneticAlgorithm(p).minimise(8, eval.callback());
  ASSERT_EQ(r.bestHistory.size(), static_cast<std::size_t>(r.generations));
  ASSERT_EQ(r.evaluationsPerGeneration.size(), r.bestHistory.size());
  std::size_t seen = 0;
  double runningMin = std::numeric_limits<double>::infinity();
  for (std::size_t g = 0; g < r.bestHistory.size(); ++g) {
    if (g > 0) EXPECT_LE(r.bestHistory[g], r.bestHistory[g - 1]) << "generation " << g;
    for (std::size_t k = 0; k < r.evaluationsPerGeneration[g]; ++k)
      runningMin = std::min(runningMin, eval.all[seen++]);
    EXPECT_EQ(r.bestHistory[g], runningMin) << "generation " << g;
  }
  EXPECT_EQ(seen, eval.all.size());
  EXPECT_DOUBLE_EQ(deceptiveTrap(r.best), r.bestObjective);
}

TEST(ElitistGeneticAlgorithmBinary, BestIsTheFirstEvaluatedGenomeOfTheLowestObjective) {
  // The caller keeps the trial state of a candidate only when it beats every earlier one; that
  // candidate must be the GA's answer, also when many genomes tie (here objectives take only
  // four values).
  auto coarse = [](const Genome &g) {
    int ones = 0;
    for (double u : g) ones += u == 1.0;
    return ones == 4 ? 1.0 : 2.0 + ones % 3; // 126 genomes share the minimum, none a corner
  };
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    GeneticAlgorithmParameters p;
    p.populationSize = 8;
    p.generations = 12;
    p.stagnationGenerations = 0;
    p.seed = seed;
    RecordingEvaluator eval{coarse};
    const GeneticAlgorithmResult r = ElitistGeneticAlgorithm(p).minimise(9, eval.callback());
    Genome firstBest;
    double lowest = std::numeric_limits<double>::infinity();
    for (const auto &batch : eval.batches)
      for (const Genome &g : batch)
        if (coarse(g) < lowest) {
          lowest = coarse(g);
          firstBest = g;
        }
    EXPECT_EQ(r.best, firstBest) << "seed " << seed;
    EXPECT_EQ(r.bestObjective, lowest);
  }
}

TEST(ElitistGeneticAlgorithmBinary, SameSeedSameRunOtherSeedsDiffer) {
  GeneticAlgorithmParameters p;
  p.populationSize = 20;
  p.generations = 15;
  p.stagnationGenerations = 0;
  const std::size_t n = kWeights.size();
  auto run = [&](std::uint64_t seed, RecordingEvaluator &eval) {
    p.seed = seed;
    return ElitistGeneticAlgorithm(p).minimise(n, eval.callback());
  };
  RecordingEvaluator a{weightedSum}, b{weightedSum};
  const GeneticAlgorithmResult ra = run(42, a), rb = run(42, b);
  EXPECT_EQ(ra.bestHistory, rb.bestHistory);
  EXPECT_EQ(ra.best, rb.best);
  EXPECT_EQ(ra.evaluationsPerGeneration, rb.evaluationsPerGeneration);
  EXPECT_EQ(a.batches, b.batches);  // the same genomes, in the same order

  // The seed is used: some other seed gives another sequence of candidates.
  bool differs = false;
  for (std::uint64_t seed : {43u, 44u, 45u}) {
    RecordingEvaluator c{weightedSum};
    run(seed, c);
    differs = differs || c.batches != a.batches;
  }
  EXPECT_TRUE(differs);
}

TEST(ElitistGeneticAlgorithmBinary, GenerationZeroHoldsSeedsThenCorners) {
  const std::size_t n = 5;
  GeneticAlgorithmParameters p;
  p.populationSize = 10;
  p.generations = 1;
  RecordingEvaluator eval{weightedSum};
  const GeneticAlgorithmResult r = ElitistGeneticAlgorithm(p).minimise(n, eval.callback());
  ASSERT_FALSE(eval.batches.empty());
  const std::vector<Genome> &first = eval.batches.front();
  ASSERT_EQ(first.size(), 10u);  // all distinct
  EXPECT_EQ(first[0], Genome(n, 0.0));
  EXPECT_EQ(first[1], Genome(n, 1.0));
  for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(first[2 + i], bits(n, 1u << i));
  EXPECT_EQ(r.stopReason, StopReason::generationLimit);
  EXPECT_EQ(r.generations, 1);

  // A small population takes the corners in order, as many as fit, after the seed.
  p.populationSize = 4;
  const Genome seed = {1, 0, 1, 1, 0};
  const std::vector<Genome> initial = ElitistGeneticAlgorithm(p).initialPopulation(n, {seed});
  ASSERT_EQ(initial.size(), 4u);
  EXPECT_EQ(initial[0], seed);
  EXPECT_EQ(initial[1], Genome(n, 0.0));
  EXPECT_EQ(initial[2], Genome(n, 1.0));
  EXPECT_EQ(initial[3], bits(n, 1u));
  // A seed equal to a corner is not evaluated twice.
  const std::vector<Genome> again = ElitistGeneticAlgorithm(p).initialPopulation(n, {Genome(n, 1.0)});
  EXPECT_EQ(std::set<Genome>(again.begin(), again.end()).size(), again.size());
}

TEST(ElitistGeneticAlgorithmBinary, CacheNeverEvaluatesAGenomeTwice) {
  // n = 3: at most 8 distinct genomes, however long the run; the search stops once it has
  // seen them all, with the brute-force optimum.
  auto f = [](const Genome &g) {
    return std::pow(g[0] - 1.0, 2) + 2.0 * g[1] + std::abs(g[2] - 1.0) + 0.5 * g[0] * g[2];
  };
  GeneticAlgorithmParameters p;
  p.populationSize = 6;
  p.eliteCount = 2;
  p.generations = 500;
  p.stagnationGenerations = 0;
  p.mutationRate = 0.3;
  RecordingEvaluator eval{f};
  const GeneticAlgorithmResult r = ElitistGeneticAlgorithm(p).minimise(3, eval.callback());
  std::set<Genome> distinct;
  for (const auto &b : eval.batches) distinct.insert(b.begin(), b.end());
  EXPECT_EQ(eval.calls(), distinct.size());
  EXPECT_EQ(r.evaluations, distinct.size());
  EXPECT_LE(distinct.size(), 8u);
  EXPECT_EQ(r.stopReason, StopReason::searchSpaceExhausted);
  EXPECT_EQ(r.evaluations, 8u);
  EXPECT_EQ(r.best, bruteForce(3, f).second.front());

  // A larger problem over many generations: still every genome at most once.
  p.populationSize = 12;
  p.generations = 60;
  RecordingEvaluator big{deceptiveTrap};
  const GeneticAlgorithmResult rb = ElitistGeneticAlgorithm(p).minimise(8, big.callback());
  std::set<Genome> distinctBig;
  for (const auto &b : big.batches) distinctBig.insert(b.begin(), b.end());
  EXPECT_EQ(big.calls(), distinctBig.size());
  EXPECT_EQ(rb.evaluations, distinctBig.size());
}

TEST(ElitistGeneticAlgorithmBinary, StopsOnToleranceAndOnStagnation) {
  GeneticAlgorithmParameters p;
  p.populationSize = 8;
  p.generations = 100;
  // The all-off corner already reaches the tolerance: one generation.
  p.objectiveTolerance = 1.0;
  auto distanceFromOff = [](const Genome &g) {
    double s = 0.0;
    for (double u : g) s += u;
    return s;
  };
  RecordingEvaluator eval{distanceFromOff};
  GeneticAlgorithmResult r = ElitistGeneticAlgorithm(p).minimise(10, eval.callback());
  EXPECT_EQ(r.stopReason, StopReason::objectiveTolerance);
  EXPECT_EQ(r.generations, 1);
  EXPECT_EQ(r.best, Genome(10, 0.0));

  // With the optimum found in generation 0 and nothing better to find, the run stops after
  // `stagnationGenerations` more generations.
  p.objectiveTolerance = 0.0;
  p.stagnationGenerations = 4;
  auto shifted = [&](const Genome &g) { return 1.0 + distanceFromOff(g); };
  RecordingEvaluator eval2{shifted};
  r = ElitistGeneticAlgorithm(p).minimise(10, eval2.callback());
  EXPECT_EQ(r.stopReason, StopReason::stagnation);
  EXPECT_EQ(r.generations, 5);
  EXPECT_DOUBLE_EQ(r.bestObjective, 1.0);
}

TEST(ElitistGeneticAlgorithmBinary, NoGenesIsOneEvaluation) {
  GeneticAlgorithmParameters p;
  int calls = 0;
  const GeneticAlgorithmResult r = ElitistGeneticAlgorithm(p).minimise(0, [&](const std::vector<Genome> &b) {
    calls += static_cast<int>(b.size());
    return std::vector<double>(b.size(), 2.5);
  });
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(r.best.empty());
  EXPECT_EQ(r.bestObjective, 2.5);
  EXPECT_EQ(r.stopReason, StopReason::searchSpaceExhausted);
}

TEST(ElitistGeneticAlgorithmBinary, InfiniteObjectivesAreWorstAndBadEvaluatorsAreErrors) {
  GeneticAlgorithmParameters p;
  p.generations = 3;
  // A failed solve reported as +inf never wins.
  auto failOn = [](const Genome &g) {
    return g[0] == 0.0 ? std::numeric_limits<double>::infinity() : 1.0 + g[1];
  };
  RecordingEvaluator eval{failOn};
  const GeneticAlgorithmResult r = ElitistGeneticAlgorithm(p).minimise(2, eval.callback());
  EXPECT_EQ(r.best, (Genome{1.0, 0.0}));

  const ElitistGeneticAlgorithm ga(p);
  EXPECT_THROW(
      ga.minimise(3, [](const std::vector<Genome> &b) { return std::vector<double>(b.size() + 1, 0.0); }),
      std::runtime_error);
  EXPECT_THROW(ga.minimise(3,
                           [](const std::vector<Genome> &b) {
                             return std::vector<double>(b.size(), std::numeric_limits<double>::quiet_NaN());
                           }),
               std::runtime_error);
  auto ok = [](const std::vector<Genome> &b) { return std::vector<double>(b.size(), 0.0); };
  EXPECT_THROW(ga.minimise(3, ok, {Genome{1.0, 0.0}}), std::invalid_argument);       // wrong length
  EXPECT_THROW(ga.minimise(3, ok, {Genome{1.0, 0.5, 0.0}}), std::invalid_argument);  // not binary
}

}  // namespace
}  // namespace glossa::control
