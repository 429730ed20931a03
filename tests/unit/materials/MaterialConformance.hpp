#pragma once
// The conformance checks every isochoric material passes (STYLE.md): P = d psi/dF and
// dP/dF by central finite differences at random deformation gradients, a stress-free
// reference, objectivity, and no response to pure dilatation.

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

inline void expectConformance(const materials::IsochoricMaterial &m, unsigned seed) {
  std::mt19937 rng(seed);
  const double scale = m.shearModulus();
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

} // namespace glossa::test
