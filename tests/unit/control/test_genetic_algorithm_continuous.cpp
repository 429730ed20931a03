// ElitistGeneticAlgorithm on continuous genomes in [0, 1]^4: a convex quadratic with its
// minimiser inside the box and one with the constrained minimiser on the boundary, checked
// against the closed form and against projected gradient descent; the gene grid and the cache.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <set>
#include <vector>

#include "control/ElitistGeneticAlgorithm.hpp"

namespace glossa::control {
namespace {

// f(x) = (x - c)^T A (x - c) with A symmetric positive definite and coupled.
struct Quadratic {
  Eigen::Matrix4d A;
  Eigen::Vector4d c;
  double operator()(const Eigen::Vector4d &x) const { return (x - c).dot(A * (x - c)); }
  double operator()(const Genome &g) const { return (*this)(Eigen::Vector4d(g[0], g[1], g[2], g[3])); }
};

Quadratic makeQuadratic(const Eigen::Vector4d &c) {
  Quadratic q;
  q.A << 2.0, 0.5, 0.0, 0.3,  //
      0.5, 1.5, 0.2, 0.0,     //
      0.0, 0.2, 1.0, -0.4,    //
      0.3, 0.0, -0.4, 3.0;
  q.c = c;
  return q;
}

// The minimiser over [0, 1]^4 by projected gradient descent (step 1 / ||A||_2), independent of
// the GA.
Eigen::Vector4d projectedGradientMinimiser(const Quadratic &q) {
  const double step = 1.0 / q.A.operatorNorm();
  Eigen::Vector4d x = Eigen::Vector4d::Constant(0.5);
  for (int k = 0; k < 20000; ++k) x = (x - step * 2.0 * q.A * (x - q.c)).cwiseMax(0.0).cwiseMin(1.0);
  return x;
}

GeneticAlgorithmParameters continuousParameters(std::uint64_t seed) {
  GeneticAlgorithmParameters p;
  p.geneType = GeneType::continuous;
  p.populationSize = 30;
  p.generations = 400;
  p.eliteCount = 3;
  p.tournamentSize = 3;
  p.mutationRate = 0.25;
  p.mutationSigma = 0.05;
  p.stagnationGenerations = 60;
  p.seed = seed;
  return p;
}

ElitistGeneticAlgorithm::Evaluator evaluatorOf(const Quadratic &q) {
  return [q](const std::vector<Genome> &batch) {
    std::vector<double> out;
    for (const Genome &g : batch) out.push_back(q(g));
    return out;
  };
}

Eigen::Vector4d asVector(const Genome &g) { return Eigen::Vector4d(g[0], g[1], g[2], g[3]); }

TEST(ElitistGeneticAlgorithmContinuous, InteriorMinimum) {
  const Quadratic q = makeQuadratic(Eigen::Vector4d(0.3, 0.65, 0.45, 0.2));
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const GeneticAlgorithmResult r =
        ElitistGeneticAlgorithm(continuousParameters(seed)).minimise(4, evaluatorOf(q));
    ASSERT_EQ(r.best.size(), 4u);
    EXPECT_LT((asVector(r.best) - q.c).lpNorm<Eigen::Infinity>(), 0.03) << "seed " << seed;
    EXPECT_LT(r.bestObjective, 1e-3) << "seed " << seed;
    for (double u : r.best) {
      EXPECT_GE(u, 0.0);
      EXPECT_LE(u, 1.0);
    }
  }
}

TEST(ElitistGeneticAlgorithmContinuous, BoundaryMinimum) {
  // The unconstrained minimiser lies outside the box; the constrained one has genes 0 and 1 on
  // the boundary and the others inside.
  const Quadratic q = makeQuadratic(Eigen::Vector4d(1.4, -0.3, 0.5, 0.6));
  const Eigen::Vector4d xStar = projectedGradientMinimiser(q);
  ASSERT_DOUBLE_EQ(xStar[0], 1.0);
  ASSERT_DOUBLE_EQ(xStar[1], 0.0);
  ASSERT_GT(xStar[2], 0.05);
  ASSERT_LT(xStar[2], 0.95);
  const double fStar = q(xStar);
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const GeneticAlgorithmResult r =
        ElitistGeneticAlgorithm(continuousParameters(seed)).minimise(4, evaluatorOf(q));
    EXPECT_LT((asVector(r.best) - xStar).lpNorm<Eigen::Infinity>(), 0.03) << "seed " << seed;
    EXPECT_GE(r.bestObjective, fStar - 1e-12);
    EXPECT_LT(r.bestObjective - fStar, 1e-3) << "seed " << seed;
  }
}

TEST(ElitistGeneticAlgorithmContinuous, GeneGridMakesTheCacheUseful) {
  const Quadratic q = makeQuadratic(Eigen::Vector4d(0.3, 0.65, 0.45, 0.2));
  GeneticAlgorithmParameters p = continuousParameters(5);
  p.geneResolution = 0.05;
  p.generations = 150;
  p.stagnationGenerations = 0;
  std::vector<Genome> all;
  const GeneticAlgorithmResult r =
      ElitistGeneticAlgorithm(p).minimise(4, [&](const std::vector<Genome> &batch) {
        all.insert(all.end(), batch.begin(), batch.end());
        return evaluatorOf(q)(batch);
      });
  for (const Genome &g : all)
    for (double u : g) EXPECT_NEAR(u / 0.05, std::round(u / 0.05), 1e-9) << u;
  EXPECT_EQ(std::set<Genome>(all.begin(), all.end()).size(), all.size());
  EXPECT_EQ(r.evaluations, all.size());
  // 150 generations of 27 children would be 4050 solves without the cache.
  EXPECT_LT(r.evaluations, 150u * 27u);
  // The best grid point: c rounded to the grid is within half a cell in each gene.
  EXPECT_LT((asVector(r.best) - q.c).lpNorm<Eigen::Infinity>(), 0.05 + 1e-9);
}

TEST(ElitistGeneticAlgorithmContinuous, SeedsAreSnappedAndChecked) {
  GeneticAlgorithmParameters p = continuousParameters(1);
  p.geneResolution = 0.1;
  const ElitistGeneticAlgorithm ga(p);
  const std::vector<Genome> initial = ga.initialPopulation(4, {Genome{0.33, 0.66, 1.0, 0.04}});
  ASSERT_FALSE(initial.empty());
  EXPECT_NEAR(initial[0][0], 0.3, 1e-12);
  EXPECT_NEAR(initial[0][1], 0.7, 1e-12);
  EXPECT_NEAR(initial[0][2], 1.0, 1e-12);
  EXPECT_NEAR(initial[0][3], 0.0, 1e-12);
  EXPECT_THROW(ga.initialPopulation(4, {Genome{0.3, 1.2, 0.0, 0.0}}), std::invalid_argument);
}

}  // namespace
}  // namespace glossa::control
