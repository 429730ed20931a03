#pragma once
// The conformance checks every isochoric material passes (doc/developing.md: every material
// has a finite-difference tangent test): P = d psi/dF and
// dP/dF by central finite differences at random deformation gradients, a stress-free
// reference, objectivity, and no response to pure dilatation. Helpers: centralDifferenceTangent
// (any stress function, also the history-dependent muscle law), expectConformanceAtScale
// (tolerances relative to an explicit stress scale), expectTangentConformance (laws without a
// potential, e.g. the eq. 5 stress form).

#include <random>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "materials/IsochoricMaterial.hpp"

namespace glossa::test {

inline Eigen::Matrix3d randomDeformationGradient(std::mt19937 &rng, double amplitude) {
  std::uniform_real_distribution<double> d(-amplitude, amplitude);
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) F(i, j) += d(rng);
  return F;
}

// Central finite differences of a stress function P(F): row i*3+J, column k*3+L.
template <class StressFn>
materials::Tangent9 centralDifferenceTangent(StressFn &&P, const Eigen::Matrix3d &F, double h) {
  materials::Tangent9 A;
  for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L) {
      Eigen::Matrix3d Fp = F, Fm = F;
      Fp(k, L) += h;
      Fm(k, L) -= h;
      const Eigen::Matrix3d dP = (P(Fp) - P(Fm)) / (2 * h);
      for (int i = 0; i < 3; ++i)
        for (int J = 0; J < 3; ++J) A(i * 3 + J, k * 3 + L) = dP(i, J);
    }
  return A;
}

// The checks of expectConformance for a law without a potential (e.g. the eq. 5 stress form):
// FD tangent, objectivity of P, insensitivity of the Kirchhoff stress P F^T to pure dilatation,
// and a stress-free reference. `scale` is the law's stress scale (tolerances are relative to it).
inline void expectTangentConformance(const materials::IsochoricMaterial &m, unsigned seed, double scale) {
  std::mt19937 rng(seed);
  for (int sample = 0; sample < 20; ++sample) {
    const Eigen::Matrix3d F = randomDeformationGradient(rng, 0.3);
    ASSERT_GT(F.determinant(), 0.2);
    const auto r = m.evaluate(F);
    const materials::Tangent9 fdA =
        centralDifferenceTangent([&](const Eigen::Matrix3d &G) { return m.evaluate(G).P; }, F, 1e-6);
    EXPECT_LT((fdA - r.dPdF).norm(), 1e-7 * scale) << "dP/dF wrong at sample " << sample;
    const Eigen::Matrix3d Q =
        Eigen::AngleAxisd(0.7 + sample, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    EXPECT_LT((m.evaluate(Q * F).P - Q * r.P).norm(), 1e-10 * scale);
    const Eigen::Matrix3d Fd = 1.1 * F;
    EXPECT_LT((m.evaluate(Fd).P * Fd.transpose() - r.P * F.transpose()).norm(), 1e-10 * scale);
  }
  EXPECT_LT(m.evaluate(Eigen::Matrix3d::Identity()).P.norm(), 1e-12 * scale);
}

// As expectConformance, with tolerances relative to an explicit stress scale (for composites
// whose stresses are set by a fibre law rather than by the small-strain shear modulus).
inline void expectConformanceAtScale(const materials::IsochoricMaterial &m, unsigned seed, double scale) {
  std::mt19937 rng(seed);
  for (int sample = 0; sample < 20; ++sample) {
    const Eigen::Matrix3d F = randomDeformationGradient(rng, 0.3);
    ASSERT_GT(F.determinant(), 0.2);
    const auto r = m.evaluate(F);
    const double h = 1e-6;
    materials::Tangent9 fdA;
    Eigen::Matrix3d fdP;
    for (int k = 0; k < 3; ++k)
      for (int L = 0; L < 3; ++L) {
        Eigen::Matrix3d Fp = F, Fm = F;
        Fp(k, L) += h;
        Fm(k, L) -= h;
        const auto rp = m.evaluate(Fp), rm = m.evaluate(Fm);
        fdP(k, L) = (rp.energy - rm.energy) / (2 * h);
        const Eigen::Matrix3d dP = (rp.P - rm.P) / (2 * h);
        for (int i = 0; i < 3; ++i)
          for (int J = 0; J < 3; ++J) fdA(i * 3 + J, k * 3 + L) = dP(i, J);
      }
    EXPECT_LT((fdP - r.P).norm(), 1e-7 * scale) << "P != dpsi/dF at sample " << sample;
    EXPECT_LT((fdA - r.dPdF).norm(), 1e-7 * scale) << "dP/dF wrong at sample " << sample;

    // Objectivity: psi(QF) = psi(F), P(QF) = Q P(F).
    const Eigen::Matrix3d Q =
        Eigen::AngleAxisd(0.7 + sample, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const auto rq = m.evaluate(Q * F);
    EXPECT_NEAR(rq.energy, r.energy, 1e-10 * scale);
    EXPECT_LT((rq.P - Q * r.P).norm(), 1e-10 * scale);

    // Isochoric: a pure dilatation changes neither energy nor deviatoric response.
    const auto rd = m.evaluate(1.1 * F);
    EXPECT_NEAR(rd.energy, r.energy, 1e-10 * scale);
  }
  const auto r0 = m.evaluate(Eigen::Matrix3d::Identity());
  EXPECT_NEAR(r0.energy, 0.0, 1e-14 * scale);
  EXPECT_LT(r0.P.norm(), 1e-12 * scale);
}

inline void expectConformance(const materials::IsochoricMaterial &m, unsigned seed) {
  expectConformanceAtScale(m, seed, m.shearModulus());
}

} // namespace glossa::test
