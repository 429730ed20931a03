#include "loads/DeadTraction.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace glossa::loads {

namespace {
constexpr double kS[4] = {-1, 1, 1, -1};
constexpr double kT[4] = {-1, -1, 1, 1};

// Shape values and the area element |dX/ds x dX/dt| at (s, t).
double areaElement(const FaceNodes &X, double s, double t, Eigen::Vector4d &N) {
  Eigen::Vector3d dXds = Eigen::Vector3d::Zero(), dXdt = Eigen::Vector3d::Zero();
  for (int a = 0; a < 4; ++a) {
    N(a) = 0.25 * (1 + kS[a] * s) * (1 + kT[a] * t);
    dXds += 0.25 * kS[a] * (1 + kT[a] * t) * X.row(a).transpose();
    dXdt += 0.25 * kT[a] * (1 + kS[a] * s) * X.row(a).transpose();
  }
  return dXds.cross(dXdt).norm();
}

template <class F> void integrate(const FaceNodes &X, F &&f) {
  const double g = 1.0 / std::sqrt(3.0);
  for (double s : {-g, g})
    for (double t : {-g, g}) {
      Eigen::Vector4d N;
      const double dA = areaElement(X, s, t, N);
      f(N, dA);
    }
}
} // namespace

FaceForces deadTractionForces(const FaceNodes &X, const Eigen::Vector3d &t) {
  FaceForces f = FaceForces::Zero();
  integrate(X, [&](const Eigen::Vector4d &N, double dA) {
    for (int a = 0; a < 4; ++a) f.segment<3>(3 * a) += N(a) * t * dA;
  });
  return f;
}

double faceArea(const FaceNodes &X) {
  double area = 0.0;
  integrate(X, [&](const Eigen::Vector4d &, double dA) { area += dA; });
  return area;
}

Eigen::Vector3d faceNormal(const FaceNodes &X) {
  const Eigen::Vector3d d1 = X.row(2) - X.row(0), d2 = X.row(3) - X.row(1);
  return d1.cross(d2).normalized();
}

} // namespace glossa::loads
