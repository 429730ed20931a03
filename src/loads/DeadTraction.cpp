#include "loads/DeadTraction.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace glossa::loads {

namespace {
constexpr double kS[4] = {-1, 1, 1, -1};
constexpr double kT[4] = {-1, -1, 1, 1};

// Shape values and the vector area element dX/ds x dX/dt (along the outward normal for the
// right-hand node order) at (s, t).
Eigen::Vector3d areaVector(const FaceNodes &X, double s, double t, Eigen::Vector4d &N) {
  Eigen::Vector3d dXds = Eigen::Vector3d::Zero(), dXdt = Eigen::Vector3d::Zero();
  for (int a = 0; a < 4; ++a) {
    N(a) = 0.25 * (1 + kS[a] * s) * (1 + kT[a] * t);
    dXds += 0.25 * kS[a] * (1 + kT[a] * t) * X.row(a).transpose();
    dXdt += 0.25 * kT[a] * (1 + kS[a] * s) * X.row(a).transpose();
  }
  return dXds.cross(dXdt);
}

// f(N, n dA) at the 2x2 Gauss points.
template <class F> void integrateVector(const FaceNodes &X, F &&f) {
  const double g = 1.0 / std::sqrt(3.0);
  for (double s : {-g, g})
    for (double t : {-g, g}) {
      Eigen::Vector4d N;
      const Eigen::Vector3d ndA = areaVector(X, s, t, N);
      f(N, ndA);
    }
}

template <class F> void integrate(const FaceNodes &X, F &&f) {
  integrateVector(X, [&](const Eigen::Vector4d &N, const Eigen::Vector3d &ndA) { f(N, ndA.norm()); });
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

double faceVolumeMoment(const FaceNodes &x) {
  double moment = 0.0;
  integrateVector(x, [&](const Eigen::Vector4d &N, const Eigen::Vector3d &ndA) {
    moment += (x.transpose() * N).dot(ndA) / 3.0;
  });
  return moment;
}

Eigen::Vector3d faceNormal(const FaceNodes &X) {
  const Eigen::Vector3d d1 = X.row(2) - X.row(0), d2 = X.row(3) - X.row(1);
  return d1.cross(d2).normalized();
}

} // namespace glossa::loads
