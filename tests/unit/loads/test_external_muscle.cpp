#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <stdexcept>

#include "loads/ExternalMuscle.hpp"
#include "materials/ContractileCurveSets.hpp"

using glossa::loads::ExternalFibre;
using glossa::loads::ExternalFibreResponse;
using glossa::loads::ExternalMuscle;
using glossa::materials::HillMuscleFibre;
using glossa::materials::HillSolveStatus;

namespace {
constexpr double kPhiF = 0.7;  // Table I

ExternalMuscle muscle(double T0s) {
  return ExternalMuscle(HillMuscleFibre::tableI(T0s, glossa::materials::physiologicalCurves()), kPhiF);
}

// A random external fibre of about 2 mm and a displacement that puts its stretch at lambda and
// tilts it off its reference direction.
struct Sample {
  ExternalFibre fibre;
  Eigen::Vector3d u;
};
Sample randomSample(std::mt19937 &rng, double lambda) {
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  Sample s;
  s.fibre.insertion = 1e-3 * Eigen::Vector3d(d(rng), d(rng), d(rng));
  const Eigen::Vector3d n0 = Eigen::Vector3d(d(rng), 2.0, d(rng)).normalized();
  const double L0 = 2e-3 * (1.0 + 0.2 * d(rng));
  s.fibre.origin = s.fibre.insertion + L0 * n0;
  s.fibre.area = 1e-6 / 64 * (1.0 + 0.5 * d(rng));
  const Eigen::Vector3d n = (n0 + 0.3 * Eigen::Vector3d(d(rng), d(rng), d(rng))).normalized();
  s.u = (s.fibre.origin - lambda * L0 * n) - s.fibre.insertion;
  return s;
}

// Central differences of the force in u, at the same history (lambda_c_old, alpha, dt).
Eigen::Matrix3d finiteDifferenceTangent(const ExternalMuscle &m, const Sample &s, double alpha, double dt,
                                        double lambdaCOld) {
  const double h = 1e-7 * (s.fibre.origin - s.fibre.insertion).norm();
  Eigen::Matrix3d K;
  for (int j = 0; j < 3; ++j) {
    Eigen::Vector3d up = s.u, um = s.u;
    up(j) += h;
    um(j) -= h;
    K.col(j) = (m.evaluate(s.fibre, up, alpha, dt, lambdaCOld).force -
                m.evaluate(s.fibre, um, alpha, dt, lambdaCOld).force) /
               (2 * h);
  }
  return K;
}
}  // namespace

// df/du against central differences at random states in the three Hill regimes: taut (active,
// series element carrying T_c), slack (active but the fibre shortening faster than the
// contractile element can follow) and purely passive (alpha = 0 and T0s = 0).
TEST(ExternalMuscle, TangentMatchesCentralDifferences) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const ExternalMuscle active = muscle(0.1), passive = muscle(0.0);
  int taut = 0, slack = 0, passiveCount = 0;
  for (int sample = 0; sample < 60; ++sample) {
    const int regime = sample % 3;
    // Slack and passive fibres carry only T_p, which is zero below lambda_f = 1.
    const double lambda = regime == 0 ? 0.85 + 0.4 * unit(rng) : 1.02 + 0.3 * unit(rng);
    const Sample state = randomSample(rng, lambda);
    const double dt = 0.005;
    double alpha = 0.0, lambdaCOld = lambda;
    if (regime == 0) {  // taut: lambda_c_old just below lambda_f
      alpha = 0.2 + 0.8 * unit(rng);
      lambdaCOld = lambda * (0.985 + 0.01 * unit(rng));
    } else if (regime == 1) {  // slack: (lambda_f - lambda_c_old) / dt < -vmax = -10 / s
      alpha = 0.2 + 0.8 * unit(rng);
      lambdaCOld = lambda + 0.1 + 0.2 * unit(rng);
    }  // else passive: a fibre without contractile element (T0s = 0)
    const ExternalMuscle &m = regime == 2 ? passive : active;
    const ExternalFibreResponse r = m.evaluate(state.fibre, state.u, alpha, dt, lambdaCOld);
    ASSERT_TRUE(glossa::materials::succeeded(r.hill.status)) << describe(r.hill.status);
    if (regime == 0) {
      ASSERT_EQ(r.hill.status, HillSolveStatus::Taut);
      EXPECT_GT(r.hill.Ts, 0.0);
      ++taut;
    } else if (regime == 1) {
      ASSERT_EQ(r.hill.status, HillSolveStatus::Slack);
      EXPECT_EQ(r.hill.Ts, 0.0);
      ++slack;
    } else {
      EXPECT_EQ(r.hill.Ts, 0.0);
      ++passiveCount;
    }
    EXPECT_GT(r.hill.T, 0.0);
    const Eigen::Matrix3d Kfd = finiteDifferenceTangent(m, state, alpha, dt, lambdaCOld);
    EXPECT_LT((r.dForceDu - Kfd).norm(), 1e-6 * r.dForceDu.norm())
        << "regime " << regime << " lambda_f " << r.lambdaF << "\n"
        << r.dForceDu << "\n"
        << Kfd;
    EXPECT_LT((r.dForceDu - r.dForceDu.transpose()).norm(), 1e-14 * r.dForceDu.norm());
  }
  EXPECT_EQ(taut, 20);
  EXPECT_EQ(slack, 20);
  EXPECT_EQ(passiveCount, 20);
}

// The force points from the insertion's current position to the origin, with the magnitude
// A phi_f lambda_f T_f of eq. 23, lambda_f from the geometry and T_f from the Hill fibre called
// directly; the lambda_c to commit is the Hill fibre's.
TEST(ExternalMuscle, ForceAlongTheLineToTheOriginWithEq23Magnitude) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const ExternalMuscle m = muscle(0.1);
  for (int sample = 0; sample < 20; ++sample) {
    const double lambda = 0.9 + 0.3 * unit(rng), alpha = unit(rng), lambdaCOld = lambda * 0.99;
    const Sample s = randomSample(rng, lambda);
    const ExternalFibreResponse r = m.evaluate(s.fibre, s.u, alpha, 0.005, lambdaCOld);
    ASSERT_TRUE(glossa::materials::succeeded(r.hill.status));
    const Eigen::Vector3d toOrigin = s.fibre.origin - (s.fibre.insertion + s.u);
    const double L0 = (s.fibre.origin - s.fibre.insertion).norm();
    EXPECT_NEAR(r.lambdaF, toOrigin.norm() / L0, 1e-14);
    EXPECT_NEAR(r.lambdaF, lambda, 1e-12);
    const auto hill = m.fibre().evaluate({toOrigin.norm() / L0, alpha, 0.005, lambdaCOld});
    ASSERT_GT(hill.T, 0.0);
    EXPECT_LT(r.force.cross(toOrigin).norm(), 1e-12 * r.force.norm() * toOrigin.norm());
    EXPECT_GT(r.force.dot(toOrigin), 0.0);
    EXPECT_NEAR(r.force.norm(), s.fibre.area * kPhiF * lambda * hill.T, 1e-10 * r.force.norm());
    EXPECT_NEAR(r.hill.lambdaC, hill.lambdaC, 1e-14);
  }
}

// A passive fibre along y stretched to lambda_f = 1.1: the parallel element of Table I by hand,
// T_p = 2 a A T0max (lambda - 1) exp(a (lambda - 1)^2) = 1613.0939 Pa, and its tangent.
TEST(ExternalMuscle, PassiveFibreHandValues) {
  const ExternalMuscle m = muscle(0.0);
  const ExternalFibre fibre{{0.0, 3e-3, 0.0}, {0.0, 1e-3, 0.0}, 0.25e-6};
  const ExternalFibreResponse r = m.evaluate(fibre, {0.0, -0.2e-3, 0.0}, 0.0, 0.005, 1.0);
  EXPECT_NEAR(r.lambdaF, 1.1, 1e-14);
  EXPECT_NEAR(r.hill.T, 1613.0939065692837, 1e-9);
  const double f = 0.00031052057701458715;  // A phi_f lambda_f T_p [N]
  EXPECT_LT((r.force - Eigen::Vector3d(0, f, 0)).norm(), 1e-12 * f);
  // df/du = -A phi_f [ (T + lambda T') / L0 e_y e_y + lambda T / L (I - e_y e_y) ].
  const Eigen::Matrix3d K =
      Eigen::Vector3d(-0.14114571682481233, -2.0797256791268786, -0.14114571682481233).asDiagonal();
  EXPECT_LT((r.dForceDu - K).norm(), 1e-10 * K.norm());
  // Unstretched and inactive: no force.
  EXPECT_EQ(m.evaluate(fibre, Eigen::Vector3d::Zero(), 0.0, 0.005, 1.0).force.norm(), 0.0);
}

TEST(ExternalMuscle, InvalidGeometry) {
  const ExternalMuscle m = muscle(0.1);
  const ExternalFibre collapsed{{1e-3, 2e-3, 0.0}, {1e-3, 2e-3, 0.0}, 1e-8};
  EXPECT_THROW(m.evaluate(collapsed, Eigen::Vector3d::Zero(), 0.5, 0.005, 1.0), std::invalid_argument);
  const ExternalFibre negativeArea{{0.0, 3e-3, 0.0}, {0.0, 1e-3, 0.0}, -1.0};
  EXPECT_THROW(m.evaluate(negativeArea, Eigen::Vector3d::Zero(), 0.5, 0.005, 1.0), std::invalid_argument);
  // The insertion displaced onto the origin: no direction, reported, NaN force.
  const ExternalFibre fibre{{0.0, 3e-3, 0.0}, {0.0, 1e-3, 0.0}, 1e-8};
  const ExternalFibreResponse r = m.evaluate(fibre, {0.0, 2e-3, 0.0}, 0.5, 0.005, 1.0);
  EXPECT_EQ(r.hill.status, HillSolveStatus::InvalidInput);
  EXPECT_TRUE(std::isnan(r.force(0)));
  EXPECT_THROW(ExternalMuscle(HillMuscleFibre::tableI(0.1, glossa::materials::physiologicalCurves()), 0.0),
               std::invalid_argument);
}

// Eq. 26 on hand values: P^O = (cs P^I_x, P^I_y + h, cs P^I_z), h = 2 mm.
TEST(ExternalMuscle, SpacingRuleEq26) {
  using glossa::loads::spacingRuleOrigin;
  const Eigen::Vector3d PI(0.5e-3, 1e-3, 0.25e-3);
  EXPECT_LT((spacingRuleOrigin(PI, 1.0, 2e-3) - Eigen::Vector3d(0.5e-3, 3e-3, 0.25e-3)).norm(), 1e-18);
  EXPECT_LT((spacingRuleOrigin(PI, 2.0, 2e-3) - Eigen::Vector3d(1e-3, 3e-3, 0.5e-3)).norm(), 1e-18);
  // Another axis and a centre: height along z, x and y scaled about (1, 1, 0) mm.
  EXPECT_LT((spacingRuleOrigin(PI, 3.0, 1e-3, 2, Eigen::Vector3d(1e-3, 1e-3, 0.0)) -
             Eigen::Vector3d(-0.5e-3, 1e-3, 1.25e-3))
                .norm(),
            1e-18);
  EXPECT_THROW(spacingRuleOrigin(PI, 1.0, 2e-3, 3), std::invalid_argument);
}

// Nodal tributary areas: a trapezoid by hand (int N_a dA = 5/12, 5/12, 1/3, 1/3), and a
// non-uniform 3 x 2 grid of rectangles on the plane y = 1 (each rectangle gives a quarter of its
// area to each corner) whose areas sum to the rectangle's.
TEST(ExternalMuscle, TributaryAreas) {
  glossa::loads::FaceNodes trapezoid;
  trapezoid << 0, 0, 0, 2, 0, 0, 1.5, 1, 0, 0.5, 1, 0;
  const Eigen::Vector4d At = glossa::loads::faceTributaryAreas(trapezoid);
  EXPECT_LT((At - Eigen::Vector4d(5.0 / 12, 5.0 / 12, 1.0 / 3, 1.0 / 3)).norm(), 1e-14);

  const double xs[4] = {0.0, 1.0, 1.5, 3.0}, zs[3] = {0.0, 0.5, 2.0};
  std::vector<Eigen::Vector3d> nodes;
  for (double z : zs)
    for (double x : xs) nodes.emplace_back(x, 1.0, z);
  std::vector<glossa::loads::FaceNodeIds> faces;
  for (std::int64_t j = 0; j < 2; ++j)
    for (std::int64_t i = 0; i < 3; ++i) {
      const std::int64_t n0 = 4 * j + i;
      faces.push_back({n0, n0 + 4, n0 + 5, n0 + 1});  // outward +y
    }
  const auto areas = glossa::loads::tributaryAreas(faces, nodes);
  ASSERT_EQ(areas.size(), 12u);
  double sum = 0.0;
  for (const auto &[id, A] : areas) sum += A;
  EXPECT_NEAR(sum, 3.0 * 2.0, 1e-14);
  EXPECT_NEAR(areas.at(0), 0.5 / 4, 1e-15);                        // corner (0, 0)
  EXPECT_NEAR(areas.at(5), (0.5 + 0.25 + 1.5 + 0.75) / 4, 1e-15);  // interior (1, 0.5)
  EXPECT_NEAR(areas.at(11), 1.5 * 1.5 / 4, 1e-15);                 // corner (3, 2)
  EXPECT_NEAR(areas.at(3), 1.5 * 0.5 / 4, 1e-15);                  // corner (3, 0)
  EXPECT_NEAR(areas.at(7), (1.5 * 0.5 + 1.5 * 1.5) / 4, 1e-15);    // edge (3, 0.5)
  EXPECT_THROW(glossa::loads::tributaryAreas({{0, 1, 2, 99}}, nodes), std::invalid_argument);
}
