#include "app/DeformationPath.hpp"

#include <cmath>

namespace glossa::app {

double pathParameter(const input::PointParameters &point, double t) {
  return point.path == input::PointPath::table ? 0.0 : point.amplitude * point.scale(t);
}

Eigen::Matrix3d deformationGradient(const input::PointParameters &point, double t) {
  const Eigen::Vector3d &e = point.direction;
  if (point.path == input::PointPath::uniaxial) {
    const double lambda = 1.0 + pathParameter(point, t);
    const Eigen::Matrix3d ee = e * e.transpose();
    return lambda * ee + (Eigen::Matrix3d::Identity() - ee) / std::sqrt(lambda);
  }
  if (point.path == input::PointPath::simpleShear)
    return Eigen::Matrix3d::Identity() + pathParameter(point, t) * e * point.shearPlaneNormal.transpose();
  const auto &times = point.times;
  const auto &table = point.table;
  if (t <= times.front()) return table.front();
  for (std::size_t k = 1; k < times.size(); ++k)
    if (t <= times[k]) {
      const double s = (t - times[k - 1]) / (times[k] - times[k - 1]);
      return (1 - s) * table[k - 1] + s * table[k];
    }
  return table.back();
}

} // namespace glossa::app
