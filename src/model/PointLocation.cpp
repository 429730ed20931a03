#include "model/PointLocation.hpp"

#include <Eigen/LU>

#include "fem/HexShape.hpp"

namespace glossa::model {

std::optional<ElementPoint> locatePoint(const mesh::HexMesh &mesh, const Eigen::Vector3d &x, double tolerance) {
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    const Eigen::Matrix<double, 8, 3> X = mesh.elementCoordinates(static_cast<mesh::ElementId>(e));
    const Eigen::Vector3d lo = X.colwise().minCoeff().transpose(), hi = X.colwise().maxCoeff().transpose();
    const double slack = 1e-9 * (hi - lo).norm();
    if (((x - lo).array() < -slack).any() || ((x - hi).array() > slack).any()) continue;
    // Newton on X(xi) = x from the centre; trilinear maps of sound elements converge in a few steps.
    Eigen::Vector3d xi = Eigen::Vector3d::Zero();
    bool converged = false;
    for (int k = 0; k < 30 && !converged; ++k) {
      const Eigen::Vector3d r = X.transpose() * fem::hexShape(xi) - x;
      const Eigen::Matrix3d dXdxi = X.transpose() * fem::hexShapeGradient(xi);
      const Eigen::Vector3d step = dXdxi.partialPivLu().solve(r);
      xi -= step;
      converged = step.cwiseAbs().maxCoeff() < 1e-14;
      if (xi.cwiseAbs().maxCoeff() > 3.0) break; // far outside: not this element
    }
    if (converged && xi.cwiseAbs().maxCoeff() <= 1.0 + tolerance)
      return ElementPoint{static_cast<mesh::ElementId>(e), xi.cwiseMax(-1.0).cwiseMin(1.0)};
  }
  return std::nullopt;
}

std::optional<mesh::NamedPoint> probeAt(const mesh::HexMesh &mesh, const Eigen::Vector3d &x) {
  const auto at = locatePoint(mesh, x);
  if (!at) return std::nullopt;
  const auto &hex = mesh.elements[static_cast<std::size_t>(at->element)];
  const Eigen::Matrix<double, 8, 1> N = fem::hexShape(at->xi);
  mesh::NamedPoint p{x, hex[0], {}};
  int nearest = 0;
  for (int a = 0; a < 8; ++a) {
    p.weights.emplace_back(hex[a], N(a));
    if ((mesh.nodes[hex[a]] - x).norm() < (mesh.nodes[hex[nearest]] - x).norm()) nearest = a;
  }
  p.node = hex[nearest];
  return p;
}

} // namespace glossa::model
