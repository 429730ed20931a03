#include "loads/FollowerPressure.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "loads/FaceShape.hpp"

namespace glossa::loads {

const std::array<Eigen::Vector2d, 4> &followerPressureGaussCoordinates() {
  static const std::array<Eigen::Vector2d, 4> points = [] {
    const double g = 1.0 / std::sqrt(3.0);
    return std::array<Eigen::Vector2d, 4>{Eigen::Vector2d(-g, -g), Eigen::Vector2d(g, -g),
                                          Eigen::Vector2d(g, g), Eigen::Vector2d(-g, g)};
  }();
  return points;
}

std::array<Eigen::Vector3d, 4> followerPressureGaussPoints(const FaceNodes &X) {
  std::array<Eigen::Vector3d, 4> points;
  for (std::size_t q = 0; q < 4; ++q) {
    const Eigen::Vector2d &st = followerPressureGaussCoordinates()[q];
    points[q] = X.transpose() * faceShape(st(0), st(1)).N;
  }
  return points;
}

FaceForces followerPressureForces(const FaceNodes &X, const FaceNodes &u,
                                  const std::array<double, 4> &pAtGaussPoints, FaceTangent *K) {
  const FaceNodes x = X + u;
  FaceForces f = FaceForces::Zero();
  if (K) K->setZero();
  // The 2x2 Gauss weights are 1.
  for (std::size_t q = 0; q < 4; ++q) {
    const Eigen::Vector2d &st = followerPressureGaussCoordinates()[q];
    const FaceShape pt = faceShape(st(0), st(1));
    const Eigen::Vector3d xs = x.transpose() * pt.dNds, xt = x.transpose() * pt.dNdt;
    const double p = pAtGaussPoints[q];
    // n da = x_,s x x_,t ds dt: the area vector of the deformed face.
    const Eigen::Vector3d nda = xs.cross(xt);
    for (int a = 0; a < 4; ++a) f.segment<3>(3 * a) -= p * pt.N(a) * nda;
    if (!K) continue;
    // d(x_,s x x_,t)/du_b = dN_b/ds (.) x x_,t + x_,s x dN_b/dt (.) = N_b,t [x_,s]_x - N_b,s [x_,t]_x.
    const Eigen::Matrix3d Ss = crossMatrix(xs), St = crossMatrix(xt);
    for (int b = 0; b < 4; ++b) {
      const Eigen::Matrix3d dnda = pt.dNdt(b) * Ss - pt.dNds(b) * St;
      for (int a = 0; a < 4; ++a) K->block<3, 3>(3 * a, 3 * b) -= p * pt.N(a) * dnda;
    }
  }
  return f;
}

FaceForces followerPressureForces(const FaceNodes &X, const FaceNodes &u, double p, FaceTangent *K) {
  return followerPressureForces(X, u, {p, p, p, p}, K);
}

}  // namespace glossa::loads
