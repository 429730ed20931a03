// Body forces against integrals computed independently: on a distorted hexahedron the nodal
// forces sum to b V and their first moment sum_a X_a f_a equals b times the first moment of
// volume (the Gauss rule is exact for both: the integrands are polynomials of degree <= 3 per
// coordinate times the trilinear Jacobian). Posture gravity follows doc/loads.md's body frame.
#include <gtest/gtest.h>

#include "fem/HexShape.hpp"
#include "loads/BodyForce.hpp"

using namespace glossa;

TEST(BodyForce, TotalForceAndFirstMomentOnADistortedHex) {
  loads::HexNodes X;
  X << 0, 0, 0, 2, 0.1, 0, 2.2, 1.5, 0.2, -0.1, 1, 0, 0, 0.2, 1, 2, 0, 1.3, 2.1, 1.2, 1.1, 0, 1.1, 0.9;
  const Eigen::Vector3d b(1.5, -9.81, 0.3);
  const loads::HexForces f = loads::bodyForces(X, b);
  // Volume and first moment of volume by a fine midpoint sum over the reference cube.
  double V = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  const int n = 40;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Eigen::Vector3d xi(-1 + (2 * i + 1.0) / n, -1 + (2 * j + 1.0) / n, -1 + (2 * k + 1.0) / n);
        Eigen::Matrix<double, 8, 3> dNdX;
        double detJ = 0.0;
        ASSERT_TRUE(fem::hexGradients(X, xi, dNdX, detJ));
        const double w = detJ * 8.0 / (n * n * n);
        V += w;
        moment += w * (X.transpose() * fem::hexShape(xi));
      }
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  Eigen::Matrix3d firstMoment = Eigen::Matrix3d::Zero(); // sum_a X_a (x) f_a
  for (int a = 0; a < 8; ++a) {
    total += f.segment<3>(3 * a);
    firstMoment += X.row(a).transpose() * f.segment<3>(3 * a).transpose();
  }
  EXPECT_LT((total - V * b).norm(), 1e-4 * V * b.norm()); // midpoint-sum accuracy
  EXPECT_LT((firstMoment - moment * b.transpose()).norm(), 1e-4 * moment.norm() * b.norm());
}

TEST(BodyForce, PostureGravity) {
  EXPECT_EQ(loads::postureGravity("upright", 9.81), Eigen::Vector3d(0, -9.81, 0));
  EXPECT_EQ(loads::postureGravity("supine", 9.81), Eigen::Vector3d(-9.81, 0, 0));
  EXPECT_THROW(loads::postureGravity("prone", 9.81), std::invalid_argument);
}
