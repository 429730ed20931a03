#include "loads/FaceShape.hpp"

namespace glossa::loads {

namespace {
constexpr double kS[4] = {-1, 1, 1, -1};
constexpr double kT[4] = {-1, -1, 1, 1};
}  // namespace

FaceShape faceShape(double s, double t) {
  FaceShape q;
  for (int a = 0; a < 4; ++a) {
    q.N(a) = 0.25 * (1 + kS[a] * s) * (1 + kT[a] * t);
    q.dNds(a) = 0.25 * kS[a] * (1 + kT[a] * t);
    q.dNdt(a) = 0.25 * kT[a] * (1 + kS[a] * s);
  }
  return q;
}

Eigen::Matrix3d crossMatrix(const Eigen::Vector3d &v) {
  Eigen::Matrix3d S;
  S << 0, -v(2), v(1), v(2), 0, -v(0), -v(1), v(0), 0;
  return S;
}

}  // namespace glossa::loads
