#pragma once
// The genome and the parameters of the elitist genetic algorithm (paper §6.1; doc/control.md).
// A genome holds one neural input u_M in [0, 1] per evaluated muscle group, so the caller can
// hand a genome's genes straight to the step's neural inputs (the model evaluator's p2).

#include <cstdint>
#include <string>
#include <vector>

namespace glossa::control {

// Genes are doubles in both variants: binary genomes hold exactly 0.0 or 1.0 (the paper's
// on/off inputs), continuous ones any value in [0, 1].
using Genome = std::vector<double>;

enum class GeneType { binary, continuous };

struct GeneticAlgorithmParameters {
  GeneType geneType = GeneType::binary;
  int populationSize = 16;          // genomes per generation, [2, inf)
  int generations = 20;             // generation limit, generation 0 included, [1, inf)
  int eliteCount = 2;               // best distinct genomes copied unchanged, [1, populationSize - 1]
  int tournamentSize = 2;           // genomes drawn per selection, best one wins, [1, populationSize]
  double crossoverRate = 0.9;       // probability that a child is a uniform crossover, [0, 1]
  double mutationRate = 0.1;        // per gene: bit flip or Gaussian step, [0, 1]
  double mutationSigma = 0.1;       // standard deviation of the Gaussian step (continuous), (0, inf)
  double geneResolution = 0.0;      // continuous genes snapped to multiples of it (0: off), [0, 0.5]
  int stagnationGenerations = 5;    // stop after this many generations without improvement (0: off)
  double minImprovement = 0.0;      // a best objective must fall by more than this to count, [0, inf)
  double objectiveTolerance = 0.0;  // stop as soon as the best objective is <= this, [0, inf)
  std::uint64_t seed = 1;           // of the std::mt19937_64 stream

  // Throws std::invalid_argument naming the first bad field (prefixed by `prefix`, e.g. "ga.")
  // and its allowed range.
  void validate(const std::string &prefix = "") const;
};

}  // namespace glossa::control
