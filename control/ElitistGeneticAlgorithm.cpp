#include "control/ElitistGeneticAlgorithm.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>

#include "control/RandomStream.hpp"

namespace glossa::control {
namespace {

// Attempts at drawing a genome not yet in the generation being built before a duplicate is
// accepted (unavoidable when the binary search space is smaller than the population).
constexpr int kDuplicateAttempts = 16;

// Continuous genes live on the grid of `resolution` (when > 0) clipped to [0, 1], so that a
// genome reached twice is recognised by the cache (doc/control.md, "Caching").
double snapGene(double u, const GeneticAlgorithmParameters &p) {
  if (p.geneType == GeneType::binary) return u;
  if (p.geneResolution > 0.0) u = std::round(u / p.geneResolution) * p.geneResolution;
  return std::clamp(u, 0.0, 1.0);
}

Genome checkedSeed(const Genome &seed, std::size_t genes, const GeneticAlgorithmParameters &p) {
  if (seed.size() != genes) {
    std::ostringstream s;
    s << "ElitistGeneticAlgorithm: a seed has " << seed.size() << " genes, the search " << genes;
    throw std::invalid_argument(s.str());
  }
  Genome g(seed.size());
  for (std::size_t i = 0; i < genes; ++i) {
    const double u = seed[i];
    const bool ok = p.geneType == GeneType::binary ? (u == 0.0 || u == 1.0) : (u >= 0.0 && u <= 1.0);
    if (!ok) {
      std::ostringstream s;
      s << "ElitistGeneticAlgorithm: seed gene " << i << " = " << u << " is not "
        << (p.geneType == GeneType::binary ? "0 or 1" : "in [0, 1]");
      throw std::invalid_argument(s.str());
    }
    g[i] = snapGene(u, p);
  }
  return g;
}

Genome randomGenome(std::size_t genes, const GeneticAlgorithmParameters &p, RandomStream &rng) {
  Genome g(genes);
  for (double &u : g)
    u = p.geneType == GeneType::binary ? (rng.bernoulli(0.5) ? 1.0 : 0.0) : snapGene(rng.uniform(), p);
  return g;
}

// Generation 0 (paper §6.1: "all corners of the solution space and a prediction for the
// solution based on previous steps are evaluated"): the seeds first, so the prediction is never
// crowded out; then the corners all off, all on and each single gene on, in gene order, as many
// as fit; then random genomes. Duplicates are skipped.
std::vector<Genome> buildInitial(std::size_t genes, const std::vector<Genome> &seeds,
                                 const GeneticAlgorithmParameters &p, RandomStream &rng) {
  const std::size_t size = static_cast<std::size_t>(p.populationSize);
  std::vector<Genome> population;
  std::set<Genome> present;
  auto add = [&](Genome g) {
    if (population.size() < size && present.insert(g).second) population.push_back(std::move(g));
  };
  for (const Genome &s : seeds) add(checkedSeed(s, genes, p));
  add(Genome(genes, 0.0));
  add(Genome(genes, 1.0));
  for (std::size_t i = 0; i < genes && population.size() < size; ++i) {
    Genome g(genes, 0.0);
    g[i] = 1.0;
    add(std::move(g));
  }
  // Random genomes, distinct where the search space allows it.
  int misses = 0;
  while (population.size() < size) {
    Genome g = randomGenome(genes, p, rng);
    if (present.count(g) && ++misses <= kDuplicateAttempts * p.populationSize) continue;
    present.insert(g);
    population.push_back(std::move(g));
  }
  return population;
}

// Tournament selection on a population sorted best first: of `k` indices drawn uniformly (with
// replacement) the smallest wins, i.e. the best genome, ties going to the earlier one.
std::size_t tournament(std::size_t populationSize, int k, RandomStream &rng) {
  std::size_t winner = populationSize;
  for (int i = 0; i < k; ++i) winner = std::min<std::size_t>(winner, rng.index(populationSize));
  return winner;
}

Genome makeChild(const std::vector<Genome> &sorted, const GeneticAlgorithmParameters &p, RandomStream &rng) {
  const Genome &a = sorted[tournament(sorted.size(), p.tournamentSize, rng)];
  const Genome &b = sorted[tournament(sorted.size(), p.tournamentSize, rng)];
  Genome child = a;
  // Uniform crossover: each gene from either parent with probability 1/2.
  if (rng.bernoulli(p.crossoverRate))
    for (std::size_t i = 0; i < child.size(); ++i)
      if (rng.bernoulli(0.5)) child[i] = b[i];
  for (double &u : child) {
    if (!rng.bernoulli(p.mutationRate)) continue;
    if (p.geneType == GeneType::binary)
      u = 1.0 - u;  // bit flip
    else
      u = snapGene(u + p.mutationSigma * rng.normal(), p);  // Gaussian step, clamped to [0, 1]
  }
  return child;
}

// The next generation: the best `eliteCount` distinct genomes unchanged (elitism: the best
// objective can never increase), then children of tournament-selected parents.
std::vector<Genome> nextGeneration(const std::vector<Genome> &sorted, const GeneticAlgorithmParameters &p,
                                   RandomStream &rng) {
  std::vector<Genome> next;
  std::set<Genome> present;
  for (const Genome &g : sorted) {
    if (static_cast<int>(next.size()) == p.eliteCount) break;
    if (present.insert(g).second) next.push_back(g);
  }
  while (static_cast<int>(next.size()) < p.populationSize) {
    Genome child = makeChild(sorted, p, rng);
    for (int attempt = 1; attempt < kDuplicateAttempts && present.count(child); ++attempt)
      child = makeChild(sorted, p, rng);
    present.insert(child);
    next.push_back(std::move(child));
  }
  return next;
}

}  // namespace

std::string toString(StopReason reason) {
  switch (reason) {
    case StopReason::generationLimit:
      return "generation limit";
    case StopReason::stagnation:
      return "stagnation";
    case StopReason::objectiveTolerance:
      return "objective tolerance";
    case StopReason::searchSpaceExhausted:
      return "search space exhausted";
  }
  return "unknown";
}

ElitistGeneticAlgorithm::ElitistGeneticAlgorithm(const GeneticAlgorithmParameters &parameters)
    : parameters_(parameters) {
  parameters_.validate();
}

std::vector<Genome> ElitistGeneticAlgorithm::initialPopulation(std::size_t genes,
                                                               const std::vector<Genome> &seeds) const {
  RandomStream rng(parameters_.seed);
  return buildInitial(genes, seeds, parameters_, rng);
}

GeneticAlgorithmResult ElitistGeneticAlgorithm::minimise(std::size_t genes, const Evaluator &evaluate,
                                                         const std::vector<Genome> &seeds) const {
  const GeneticAlgorithmParameters &p = parameters_;
  RandomStream rng(p.seed);
  // Every genome ever evaluated, keyed exactly (ordered: iteration never depends on hashing).
  std::map<Genome, double> cache;
  // The size of the search space when it is finite and small enough to count.
  const bool finite = genes == 0 || (p.geneType == GeneType::binary && genes < 63);
  const std::size_t spaceSize = finite ? (std::size_t{1} << genes) : 0;

  GeneticAlgorithmResult result;
  std::vector<Genome> population = buildInitial(genes, seeds, p, rng);
  double previousBest = std::numeric_limits<double>::infinity();
  int lastImprovement = 0;
  for (int generation = 0;; ++generation) {
    // Evaluate the genomes not seen before, each once, in order of first appearance.
    std::vector<Genome> batch;
    std::set<Genome> inBatch;
    for (const Genome &g : population)
      if (!cache.count(g) && inBatch.insert(g).second) batch.push_back(g);
    if (!batch.empty()) {
      const std::vector<double> objectives = evaluate(batch);
      if (objectives.size() != batch.size()) {
        std::ostringstream s;
        s << "ElitistGeneticAlgorithm: the evaluator returned " << objectives.size() << " objectives for "
          << batch.size() << " genomes";
        throw std::runtime_error(s.str());
      }
      for (std::size_t i = 0; i < batch.size(); ++i) {
        if (std::isnan(objectives[i]))
          throw std::runtime_error(
              "ElitistGeneticAlgorithm: the evaluator returned NaN (return +inf for a "
              "candidate that cannot be evaluated)");
        cache.emplace(batch[i], objectives[i]);
      }
    }
    result.evaluationsPerGeneration.push_back(batch.size());
    result.evaluations += batch.size();
    result.generations = generation + 1;

    // Best first; the stable sort keeps population order among ties, so the elites (placed
    // first) keep their rank and the incumbent best is never displaced by an equal genome.
    std::vector<std::size_t> order(population.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
      return cache.at(population[i]) < cache.at(population[j]);
    });
    std::vector<Genome> sorted;
    sorted.reserve(order.size());
    for (std::size_t i : order) sorted.push_back(population[i]);

    const double best = cache.at(sorted.front());
    result.best = sorted.front();
    result.bestObjective = best;
    result.bestHistory.push_back(best);
    if (generation == 0 || best < previousBest - p.minImprovement) {
      lastImprovement = generation;
      previousBest = best;
    }

    if (best <= p.objectiveTolerance) {
      result.stopReason = StopReason::objectiveTolerance;
      break;
    }
    if (finite && cache.size() == spaceSize) {
      result.stopReason = StopReason::searchSpaceExhausted;
      break;
    }
    if (p.stagnationGenerations > 0 && generation - lastImprovement >= p.stagnationGenerations) {
      result.stopReason = StopReason::stagnation;
      break;
    }
    if (generation + 1 >= p.generations) {
      result.stopReason = StopReason::generationLimit;
      break;
    }
    population = nextGeneration(sorted, p, rng);
  }
  return result;
}

}  // namespace glossa::control
