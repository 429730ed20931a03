// The deformable pair kernel (contact/PairContact): the slave points' Gauss rule, the Newton
// projection onto a bilinear face against its defining conditions and a brute-force search, the
// consistent tangent against central differences on random warped pairs (active, inactive and
// mixed), and momentum conservation: a pair's forces sum to zero.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "RandomFaces.hpp"
#include "contact/PairContact.hpp"
#include "loads/FaceShape.hpp"

using namespace glossa::contact;
using glossa::loads::FaceNodes;
using glossa::test::perturbed;

namespace {

// The unit square at height z; `up`: its right-hand normal points to +z (a master below the
// slave), else to -z (a slave above, facing down).
FaceNodes square(double z, bool up) {
  FaceNodes X;
  if (up)
    X << 0, 0, z, 1, 0, z, 1, 1, z, 0, 1, z;
  else
    X << 0, 0, z, 0, 1, z, 1, 1, z, 1, 0, z;
  return X;
}

PairForces forcesAt(const FaceNodes &xs, const FaceNodes &xm, const SlavePoint &q, double lambda, double eps,
                    const Eigen::Matrix<double, 24, 1> &du) {
  FaceNodes ys = xs, ym = xm;
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) {
      ys(a, i) += du(3 * a + i);
      ym(a, i) += du(12 + 3 * a + i);
    }
  return pairPointForces(ys, q, ym, lambda, eps);
}

}  // namespace

TEST(PairContact, SlavePointsIntegrateProductsOfDegreeTwoNMinusOne) {
  for (int n = 1; n <= 6; ++n) {
    const auto points = slavePoints(n);
    ASSERT_EQ(points.size(), static_cast<std::size_t>(n * n));
    double area = 0, moment = 0;
    for (const auto &p : points) {
      area += p.weight;
      moment += p.weight * std::pow(p.st(0), 2 * n - 2) * std::pow(p.st(1), 2 * n - 2);
    }
    EXPECT_NEAR(area, 4.0, 1e-14) << n;
    // int s^k ds over [-1, 1] = 2 / (k + 1) for even k.
    EXPECT_NEAR(moment, std::pow(2.0 / (2 * n - 1), 2), 1e-14) << n;
  }
  EXPECT_THROW(slavePoints(0), std::invalid_argument);
}

TEST(PairContact, ProjectionIsTheClosestPointOfAWarpedFace) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> inPlane(0.1, 0.9), height(-0.3, 0.3);
  for (int sample = 0; sample < 50; ++sample) {
    const FaceNodes xm = perturbed(square(0, true), rng, 0.15);
    const Eigen::Vector3d x(inPlane(rng), inPlane(rng), height(rng));
    const auto p = projectOntoFace(xm, x);
    ASSERT_TRUE(p.has_value()) << sample;
    const auto sh = glossa::loads::faceShape(p->st(0), p->st(1));
    const Eigen::Vector3d d = x - xm.transpose() * sh.N;
    // The defining conditions: x - x_m along the normal, so orthogonal to both tangents.
    EXPECT_NEAR(d.dot(xm.transpose() * sh.dNds), 0.0, 1e-13) << sample;
    EXPECT_NEAR(d.dot(xm.transpose() * sh.dNdt), 0.0, 1e-13) << sample;
    EXPECT_NEAR(std::abs(p->gap), d.norm(), 1e-13) << sample;
    if (!p->inside) continue;
    // No point of a 201 x 201 grid of the face is closer.
    double closest = INFINITY;
    for (int i = 0; i <= 200; ++i)
      for (int k = 0; k <= 200; ++k) {
        const auto g = glossa::loads::faceShape(-1 + i / 100.0, -1 + k / 100.0);
        closest = std::min(closest, (x - xm.transpose() * g.N).norm());
      }
    EXPECT_LE(d.norm(), closest + 1e-12) << sample;
    EXPECT_GT(d.norm(), closest - 1e-3) << sample;
  }
}

TEST(PairContact, FlatFacesCarryTheTractionOnTheSlaveAndItsOppositeOnTheMaster) {
  // A slave square 1e-3 inside a master square, both 1 x 1: t = eps 1e-3 at every point; the
  // slave's nodal forces are the consistent forces of a uniform pressure (t/4 per node, +z), the
  // master's the opposite, since the two faces coincide in plan.
  const double eps = 1e6, p = eps * 1e-3;
  const FaceNodes xs = square(-1e-3, false), xm = square(0, true);
  PairForces total = PairForces::Zero();
  for (const auto &q : slavePoints(2)) {
    ContactPointState state;
    total += pairPointForces(xs, q, xm, 0.0, eps, &state);
    EXPECT_NEAR(state.gap, -1e-3, 1e-15);
    EXPECT_NEAR(state.pressure, p, 1e-9 * p);
    EXPECT_NEAR(state.area, 0.25, 1e-15);
  }
  for (int a = 0; a < 4; ++a) {
    EXPECT_NEAR(total(3 * a + 2), p / 4, 1e-12 * p) << "slave node " << a;
    EXPECT_NEAR(total(12 + 3 * a + 2), -p / 4, 1e-12 * p) << "master node " << a;
    EXPECT_NEAR(total.segment<2>(3 * a).norm() + total.segment<2>(12 + 3 * a).norm(), 0.0, 1e-12 * p);
  }
}

TEST(PairContact, PointBeyondTheMasterFaceCarriesNothing) {
  const FaceNodes xs = square(-1e-3, false), xm = square(0, true);
  FaceNodes shifted = xm;
  shifted.col(0).array() += 1.5;  // the master face lies beside the slave: no projection inside
  ContactPointState state;
  PairTangent K;
  const PairForces f = pairPointForces(xs, slavePoints(2)[0], shifted, 10.0, 1e6, &state, &K);
  EXPECT_EQ(f.norm(), 0.0);
  EXPECT_EQ(K.norm(), 0.0);
  EXPECT_TRUE(std::isinf(state.gap));
  EXPECT_FALSE(state.active());
}

// The tangent against central differences of the forces on random warped pairs, the slave near
// the master (open, touching or pressed in), random multipliers and three Gauss rules; every
// sample's forces sum to zero (momentum).
TEST(PairContact, TangentMatchesCentralDifferencesOnRandomPairs) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> lift(-0.05, 0.03), multiplier(0.0, 2e3), shift(-0.3, 0.3);
  const double eps = 1e5, h = 1e-7;
  int active = 0, inactive = 0;
  double worst = 0;
  for (int sample = 0; sample < 120; ++sample) {
    FaceNodes xm = perturbed(square(0, true), rng, 0.1);
    FaceNodes xs = perturbed(square(lift(rng), false), rng, 0.1);
    const double dx = shift(rng), dy = shift(rng);
    xs.col(0).array() += dx;
    xs.col(1).array() += dy;
    const int n = 1 + sample % 3;
    const double lambda = sample % 4 == 0 ? 0.0 : multiplier(rng);
    for (const auto &q : slavePoints(n)) {
      ContactPointState state;
      PairTangent K;
      const PairForces f = pairPointForces(xs, q, xm, lambda, eps, &state, &K);
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (int a = 0; a < 8; ++a) sum += f.segment<3>(3 * a);
      EXPECT_LE(sum.norm(), 1e-12 * (1.0 + f.norm())) << sample;
      if (!std::isfinite(state.gap)) continue;
      // Skip points within a difference step of the kink or of the master's edge.
      const double trial = lambda - eps * state.gap;
      if (std::abs(trial) < 1.0) continue;
      const auto p = projectOntoFace(xm, xs.transpose() * glossa::loads::faceShape(q.st(0), q.st(1)).N);
      if (std::abs(p->st.cwiseAbs().maxCoeff() - 1.0) < 1e-4) continue;
      PairTangent Kfd;
      for (int c = 0; c < 24; ++c) {
        Eigen::Matrix<double, 24, 1> du = Eigen::Matrix<double, 24, 1>::Zero();
        du(c) = h;
        Kfd.col(c) = (forcesAt(xs, xm, q, lambda, eps, du) - forcesAt(xs, xm, q, lambda, eps, -du)) / (2 * h);
      }
      if (state.active()) {
        ++active;
        const double error = (K - Kfd).norm() / K.norm();
        worst = std::max(worst, error);
        EXPECT_LT(error, 1e-6) << "sample " << sample;
      } else {
        ++inactive;
        EXPECT_EQ(K.norm(), 0.0);
        EXPECT_EQ(Kfd.norm(), 0.0);
      }
    }
  }
  EXPECT_GT(active, 200);
  EXPECT_GT(inactive, 50);
  std::printf("pair tangent: %d active, %d inactive points; largest relative error %.2e\n", active, inactive,
              worst);
}
