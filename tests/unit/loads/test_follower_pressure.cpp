#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <random>

#include "loads/FollowerPressure.hpp"

using glossa::loads::FaceForces;
using glossa::loads::FaceNodes;
using glossa::loads::FaceTangent;
using glossa::loads::followerPressureForces;

namespace {

// The unit cube [0,1]^3 in VTK hex order and its six faces with the outward right-hand node
// order of mesh::kHexFaceNodes (repeated here so the test does not depend on the mesh layer).
constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                              {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
Eigen::Matrix<double, 8, 3> unitCube() {
  Eigen::Matrix<double, 8, 3> X;
  X << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1;
  return X;
}
FaceNodes faceOf(const Eigen::Matrix<double, 8, 3> &nodes, int face) {
  FaceNodes F;
  for (int a = 0; a < 4; ++a) F.row(a) = nodes.row(kFaces[face][a]);
  return F;
}

FaceNodes randomFace(std::mt19937 &rng) {
  std::uniform_real_distribution<double> d(-0.2, 0.2);
  FaceNodes X;
  X << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) X(a, i) += d(rng);
  return X;
}
FaceNodes randomDisplacement(std::mt19937 &rng, double size) {
  std::uniform_real_distribution<double> d(-size, size);
  FaceNodes u;
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) u(a, i) = d(rng);
  return u;
}

Eigen::Matrix3d rotation(double angle, const Eigen::Vector3d &axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

}  // namespace

// K = df/du against central differences of f at random (warped) faces, displacements and
// per-Gauss-point pressures.
TEST(FollowerPressure, TangentMatchesCentralDifferences) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pressure(-2.0, 3.0);
  for (int sample = 0; sample < 20; ++sample) {
    const FaceNodes X = randomFace(rng), u = randomDisplacement(rng, 0.3);
    const std::array<double, 4> p{pressure(rng), pressure(rng), pressure(rng), pressure(rng)};
    FaceTangent K;
    followerPressureForces(X, u, p, &K);
    FaceTangent Kfd;
    const double h = 1e-6;
    for (int b = 0; b < 4; ++b)
      for (int j = 0; j < 3; ++j) {
        FaceNodes up = u, um = u;
        up(b, j) += h;
        um(b, j) -= h;
        Kfd.col(3 * b + j) = (followerPressureForces(X, up, p) - followerPressureForces(X, um, p)) / (2 * h);
      }
    EXPECT_LT((K - Kfd).norm(), 1e-6 * K.norm()) << "sample " << sample;
    // Non-symmetric in general: the test would not distinguish K from K^T otherwise.
    EXPECT_GT((K - K.transpose()).norm(), 1e-3 * K.norm());
  }
}

// Uniform pressure on the closed boundary of a deformed hexahedron: the resultant and the
// resultant moment about the origin vanish (int n da = 0 and int x x n da = 0 on a closed
// surface; the 2x2 rule integrates both exactly on bilinear faces), and the assembled 24x24
// tangent is symmetric (a uniform pressure on a closed surface is conservative: it is the
// derivative of p times the enclosed volume).
TEST(FollowerPressure, ClosedSurfaceHasZeroResultantAndSymmetricTangent) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(-0.25, 0.25);
  const Eigen::Matrix<double, 8, 3> X = unitCube();
  Eigen::Matrix<double, 8, 3> u;
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) u(a, i) = d(rng);
  const double p = 1234.5;
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 24, 24> K = Eigen::Matrix<double, 24, 24>::Zero();
  double scale = 0.0;
  for (int face = 0; face < 6; ++face) {
    const FaceNodes Xf = faceOf(X, face), uf = faceOf(u, face);
    FaceTangent Kf;
    const FaceForces f = followerPressureForces(Xf, uf, p, &Kf);
    for (int a = 0; a < 4; ++a) {
      const Eigen::Vector3d fa = f.segment<3>(3 * a), xa = (Xf.row(a) + uf.row(a)).transpose();
      force += fa;
      moment += xa.cross(fa);
      scale += fa.norm();
      for (int b = 0; b < 4; ++b)
        K.block<3, 3>(3 * kFaces[face][a], 3 * kFaces[face][b]) += Kf.block<3, 3>(3 * a, 3 * b);
    }
  }
  EXPECT_GT(scale, 0.5 * p);
  EXPECT_LT(force.norm(), 1e-13 * scale);
  EXPECT_LT(moment.norm(), 1e-13 * scale);
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
}

// A flat face after a planar deformation and a rigid motion: the resultant is -p (deformed
// area) n, the area of a planar quadrilateral being half the cross product of its diagonals.
TEST(FollowerPressure, FlatFaceResultantIsMinusPressureTimesDeformedAreaTimesNormal) {
  FaceNodes X;
  X << 0, 0, 0, 2, 0, 0, 2.2, 1.5, 0, -0.1, 1.2, 0;
  FaceNodes u;  // in-plane stretch and shear, then a rotation and a translation
  const Eigen::Matrix3d Fplane = (Eigen::Matrix3d() << 1.3, 0.2, 0, -0.1, 0.8, 0, 0, 0, 1).finished();
  const Eigen::Matrix3d R = rotation(0.7, Eigen::Vector3d(1, -2, 0.5));
  const Eigen::Vector3d c(0.3, -1.0, 2.0);
  for (int a = 0; a < 4; ++a) {
    const Eigen::Vector3d Xa = X.row(a).transpose();
    u.row(a) = (R * Fplane * Xa + c - Xa).transpose();
  }
  const FaceNodes x = X + u;
  const Eigen::Vector3d d1 = (x.row(2) - x.row(0)).transpose(), d2 = (x.row(3) - x.row(1)).transpose();
  const double area = 0.5 * d1.cross(d2).norm();
  const Eigen::Vector3d n = R * Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(area, Fplane.determinant() * 0.5 * ((X.row(2) - X.row(0)).cross(X.row(3) - X.row(1))).norm(),
              1e-13);
  const double p = -500.0;
  const FaceForces f = followerPressureForces(X, u, p);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int a = 0; a < 4; ++a) sum += f.segment<3>(3 * a);
  EXPECT_LT((sum - (-p * area * n)).norm(), 1e-12 * std::abs(p) * area);
}

// Undeformed, a follower pressure is the dead traction t = -p n of the same face.
TEST(FollowerPressure, UndeformedEqualsDeadTraction) {
  FaceNodes X;
  X << 0.1, 0.0, 0.3, 1.1, 0.2, 0.1, 1.3, 1.0, 0.0, 0.0, 0.9, 0.2;
  // Make X planar: project onto the plane through node 0 with the centre normal.
  const Eigen::Vector3d n0 = glossa::loads::faceNormal(X);
  for (int a = 1; a < 4; ++a) X.row(a) -= ((X.row(a) - X.row(0)).dot(n0.transpose())) * n0.transpose();
  const Eigen::Vector3d n = glossa::loads::faceNormal(X);
  const double p = 2.5e3;
  const FaceForces follower = followerPressureForces(X, FaceNodes::Zero(), p);
  const FaceForces dead = glossa::loads::deadTractionForces(X, -p * n);
  EXPECT_LT((follower - dead).norm(), 1e-12 * dead.norm());
}

// The per-Gauss-point pressures enter as N_a p_q: a pressure on one Gauss point only gives the
// nodal forces -p N_a(s_q, t_q) (x_,s x x_,t)(s_q, t_q), checked on a parallelogram where
// x_,s x x_,t is the constant area/4 n; and the Gauss points are the images of (s_q, t_q).
TEST(FollowerPressure, PressureAtOneGaussPointAndGaussPointPositions) {
  FaceNodes X;
  X << 0, 0, 0, 2, 0, 0, 2.5, 1, 0, 0.5, 1, 0;  // parallelogram, area 2, normal +z
  const auto points = glossa::loads::followerPressureGaussPoints(X);
  const auto &st = glossa::loads::followerPressureGaussCoordinates();
  const double g = 1.0 / std::sqrt(3.0);
  for (std::size_t q = 0; q < 4; ++q) {
    const double s = st[q](0), t = st[q](1);
    EXPECT_NEAR(std::abs(s), g, 1e-15);
    EXPECT_NEAR(std::abs(t), g, 1e-15);
    // Affine map of the parallelogram: X = (1.25 + s + 0.25 t, 0.5 + 0.5 t, 0).
    EXPECT_LT((points[q] - Eigen::Vector3d(1.25 + s + 0.25 * t, 0.5 + 0.5 * t, 0)).norm(), 1e-14);
    std::array<double, 4> p{0, 0, 0, 0};
    p[q] = 8.0;
    const FaceForces f = followerPressureForces(X, FaceNodes::Zero(), p);
    const double S[4] = {-1, 1, 1, -1}, T[4] = {-1, -1, 1, 1};
    for (int a = 0; a < 4; ++a) {
      const double Na = 0.25 * (1 + S[a] * s) * (1 + T[a] * t);
      EXPECT_LT((f.segment<3>(3 * a) - (-8.0 * Na * 0.5) * Eigen::Vector3d::UnitZ()).norm(), 1e-14);
    }
  }
}
