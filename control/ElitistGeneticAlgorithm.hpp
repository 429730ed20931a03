#pragma once
// The elitist genetic algorithm that picks the neural inputs u_M of the evaluated muscle groups
// at a control step (paper §6.1: "a non-deterministic elitist GA" built on GAlib; here
// deterministic for a given seed). It minimises the eq. 25 objective, but knows nothing of it:
// the caller evaluates whole generations through a callback, e.g. by full displacement solves
// from the committed state on MPI sub-communicators. doc/control.md describes the algorithm.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "control/GeneticAlgorithmParameters.hpp"

namespace glossa::control {

enum class StopReason {
  generationLimit,      // `generations` generations were evaluated
  stagnation,           // no improvement for `stagnationGenerations` generations
  objectiveTolerance,   // the best objective reached `objectiveTolerance`
  searchSpaceExhausted  // every genome was evaluated (binary with 2^n genomes, or n = 0)
};
std::string toString(StopReason reason);

// `best` is the first genome, in evaluation order (batch by batch, each in order), whose
// objective is below every earlier one: a caller that keeps the trial state of each candidate
// that beats all earlier ones holds the winner's state when minimise() returns.
struct GeneticAlgorithmResult {
  Genome best;  // the genome of bestObjective
  double bestObjective = 0.0;
  std::vector<double> bestHistory;                    // best objective after each generation
  std::vector<std::size_t> evaluationsPerGeneration;  // distinct new genomes per generation
  std::size_t evaluations = 0;                        // distinct genomes evaluated in all
  int generations = 0;                                // generations evaluated (generation 0 included)
  StopReason stopReason = StopReason::generationLimit;
};

class ElitistGeneticAlgorithm {
 public:
  // Objectives of a batch of genomes, one per genome and in their order; lower is better.
  // Return +infinity for a candidate that cannot be evaluated (e.g. its solve failed); NaN is an
  // error. Every batch holds distinct genomes never passed before in this run.
  using Evaluator = std::function<std::vector<double>(const std::vector<Genome> &)>;

  // Throws std::invalid_argument if the parameters are invalid.
  explicit ElitistGeneticAlgorithm(const GeneticAlgorithmParameters &parameters);

  // Minimises over genomes of `genes` genes. `seeds` (each of `genes` genes in [0, 1], binary:
  // exactly 0 or 1) join the initial population first, e.g. the previous control step's best.
  // Throws std::invalid_argument for a bad seed, std::runtime_error if the evaluator returns the
  // wrong number of objectives or a NaN; the evaluator's own exceptions pass through.
  GeneticAlgorithmResult minimise(std::size_t genes, const Evaluator &evaluate,
                                  const std::vector<Genome> &seeds = {}) const;

  // The initial population as minimise() builds it (seeds, corners, random), for inspection.
  std::vector<Genome> initialPopulation(std::size_t genes, const std::vector<Genome> &seeds) const;

  const GeneticAlgorithmParameters &parameters() const { return parameters_; }

 private:
  GeneticAlgorithmParameters parameters_;
};

}  // namespace glossa::control
