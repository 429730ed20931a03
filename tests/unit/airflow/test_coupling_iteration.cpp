// The coupling's update of the sections' pressures (airflow/CouplingIteration) on fixed-point
// problems p = F(p) whose fixed point is known in closed form: an affine map F(p) = A p + b, whose
// fixed point solves (I - A) p = b.
//  - Aitken's factor on a scalar affine map is the secant's 1 / (1 - a) from its second update
//    on, which lands on the fixed point exactly;
//  - IQN-ILS on an affine map of n unknowns learns (A - I) exactly from n differences, so its
//    (n + 1)-th update lands on the fixed point;
//  - constant relaxation contracts by the relaxed map's spectral radius each iteration;
//  - Newton's method given the affine map's own Jacobian lands on its fixed point in one update;
//    given a wrong one, Broyden's updates still land on it within 2n updates (Gay 1979: Broyden's
//    method terminates on a linear system of n unknowns in at most 2n steps).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

#include "airflow/CouplingIteration.hpp"

namespace glossa::airflow {
namespace {

struct AffineMap {
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  Eigen::VectorXd operator()(const Eigen::VectorXd &p) const { return A * p + b; }
  Eigen::VectorXd fixedPoint() const {
    return (Eigen::MatrixXd::Identity(A.rows(), A.cols()) - A).partialPivLu().solve(b);
  }
};

// Non-symmetric, eigenvalues 0.9, -0.6 and 0.3 (the similarity S keeps them): the plain
// iteration (w = 1) converges slowly, by 0.9 a step.
AffineMap threeUnknowns() {
  Eigen::Matrix3d S;
  S << 1.0, 0.4, -0.2, 0.1, 1.0, 0.5, -0.3, 0.2, 1.0;
  const Eigen::Matrix3d D = Eigen::Vector3d(0.9, -0.6, 0.3).asDiagonal();
  return {S * D * S.inverse(), Eigen::Vector3d(-120.0, 35.0, -80.0)};
}

TEST(CouplingIteration, AitkenHitsTheFixedPointOfAScalarAffineMapOnItsSecondUpdate) {
  const AffineMap F{Eigen::MatrixXd::Constant(1, 1, 0.7), Eigen::VectorXd::Constant(1, -150.0)};
  CouplingIteration aitken(CouplingMethod::aitken, 0.5);
  Eigen::VectorXd p = Eigen::VectorXd::Zero(1);
  p = aitken.next(p, F(p));
  EXPECT_DOUBLE_EQ(aitken.lastRelaxation(), 0.5);
  p = aitken.next(p, F(p));
  EXPECT_NEAR(aitken.lastRelaxation(), 1.0 / (1.0 - 0.7), 1e-12);
  EXPECT_NEAR(p(0), F.fixedPoint()(0), 1e-12 * 500.0);
}

TEST(CouplingIteration, QuasiNewtonHitsTheFixedPointOfAnAffineMapAfterNPlusOneUpdates) {
  const AffineMap F = threeUnknowns();
  const Eigen::VectorXd exact = F.fixedPoint();
  CouplingIteration iqn(CouplingMethod::quasiNewton, 0.5);
  Eigen::VectorXd p = Eigen::VectorXd::Zero(3);
  for (int k = 0; k < 4; ++k) {
    EXPECT_GT((p - exact).norm(), 1e-6 * exact.norm()) << "update " << k; // not there before
    p = iqn.next(p, F(p));
  }
  EXPECT_NEAR((p - exact).norm(), 0.0, 1e-10 * exact.norm());
  // restart() forgets the model: the next update relaxes again.
  iqn.restart();
  const Eigen::VectorXd q = iqn.next(Eigen::VectorXd::Zero(3), F(Eigen::VectorXd::Zero(3)));
  EXPECT_NEAR((q - 0.5 * F.b).norm(), 0.0, 1e-14 * F.b.norm());
}

TEST(CouplingIteration, ConstantRelaxationContractsByTheRelaxedSpectralRadius) {
  // w = 0.5: the relaxed map (1 - w) I + w A has eigenvalues 0.95, 0.2, 0.65; the error's
  // component along the slowest falls by 0.95 an iteration.
  const AffineMap F = threeUnknowns();
  const Eigen::VectorXd exact = F.fixedPoint();
  CouplingIteration relaxed(CouplingMethod::constantRelaxation, 0.5);
  Eigen::VectorXd p = Eigen::VectorXd::Zero(3);
  for (int k = 0; k < 400; ++k) p = relaxed.next(p, F(p));
  const double after400 = (p - exact).norm();
  p = relaxed.next(p, F(p));
  EXPECT_NEAR((p - exact).norm() / after400, 0.95, 1e-6);
  EXPECT_DOUBLE_EQ(relaxed.lastRelaxation(), 0.5);
}

TEST(CouplingIteration, NewtonWithTheMapsJacobianHitsTheFixedPointInOneUpdate) {
  const AffineMap F = threeUnknowns();
  const Eigen::VectorXd exact = F.fixedPoint();
  CouplingIteration newton(CouplingMethod::newton, 0.5);
  EXPECT_TRUE(newton.needsJacobian());
  newton.setJacobian(F.A);
  EXPECT_FALSE(newton.needsJacobian());
  const Eigen::VectorXd p = newton.next(Eigen::VectorXd::Zero(3), F(Eigen::VectorXd::Zero(3)));
  EXPECT_NEAR((p - exact).norm(), 0.0, 1e-12 * exact.norm());
  EXPECT_DOUBLE_EQ(newton.lastRelaxation(), 1.0);
  // restart() forgets the Jacobian: a new step asks for its own.
  newton.restart();
  EXPECT_TRUE(newton.needsJacobian());
}

TEST(CouplingIteration, NewtonWithAWrongJacobianGetsThereByBroydensUpdates) {
  const AffineMap F = threeUnknowns();
  const Eigen::VectorXd exact = F.fixedPoint();
  CouplingIteration newton(CouplingMethod::newton, 0.5);
  Eigen::Matrix3d wrong = F.A;
  wrong(0, 1) += 0.3; // a Jacobian measured at another state
  wrong(2, 2) -= 0.2;
  newton.setJacobian(wrong);
  Eigen::VectorXd p = Eigen::VectorXd::Zero(3);
  p = newton.next(p, F(p));
  const double afterOne = (p - exact).norm();
  EXPECT_GT(afterOne, 1e-3 * exact.norm()); // the wrong Jacobian misses
  int updates = 1;
  while ((p - exact).norm() > 1e-10 * exact.norm() && updates < 6) {
    p = newton.next(p, F(p));
    ++updates;
  }
  EXPECT_LE((p - exact).norm(), 1e-10 * exact.norm());
  EXPECT_LE(updates, 6);
  // Without a Jacobian it relaxes as constant relaxation does.
  CouplingIteration unset(CouplingMethod::newton, 0.5);
  EXPECT_NEAR((unset.next(Eigen::VectorXd::Zero(3), F.b) - 0.5 * F.b).norm(), 0.0, 1e-14 * F.b.norm());
}

TEST(CouplingIteration, RefusesARelaxationOutsideZeroToOne) {
  EXPECT_THROW(CouplingIteration(CouplingMethod::aitken, 0.0), std::invalid_argument);
  EXPECT_THROW(CouplingIteration(CouplingMethod::aitken, 1.5), std::invalid_argument);
  EXPECT_NO_THROW(CouplingIteration(CouplingMethod::quasiNewton, 1.0));
  CouplingIteration newton(CouplingMethod::newton, 0.5);
  EXPECT_THROW(newton.setJacobian(Eigen::MatrixXd::Zero(2, 3)), std::invalid_argument);
}

}  // namespace
}  // namespace glossa::airflow
