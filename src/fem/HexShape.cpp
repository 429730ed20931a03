#include "fem/HexShape.hpp"

#include <array>

#include <algorithm>
#include <limits>

#include <cmath>

namespace glossa::fem {

namespace {
constexpr double kXi[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
constexpr double kEta[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
constexpr double kZeta[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
} // namespace

Eigen::Vector3d hexNodeXi(int a) { return {kXi[a], kEta[a], kZeta[a]}; }

const std::array<QuadraturePoint, 8> &gaussHex2() {
  static const std::array<QuadraturePoint, 8> points = [] {
    std::array<QuadraturePoint, 8> p{};
    const double g = 1.0 / std::sqrt(3.0);
    for (int a = 0; a < 8; ++a) p[a] = {g * hexNodeXi(a), 1.0};
    return p;
  }();
  return points;
}

Eigen::Matrix<double, 8, 1> hexShape(const Eigen::Vector3d &xi) {
  Eigen::Matrix<double, 8, 1> N;
  for (int a = 0; a < 8; ++a)
    N(a) = 0.125 * (1 + kXi[a] * xi(0)) * (1 + kEta[a] * xi(1)) * (1 + kZeta[a] * xi(2));
  return N;
}

Eigen::Matrix<double, 8, 3> hexShapeGradient(const Eigen::Vector3d &xi) {
  Eigen::Matrix<double, 8, 3> dN;
  for (int a = 0; a < 8; ++a) {
    const double fx = 1 + kXi[a] * xi(0), fy = 1 + kEta[a] * xi(1), fz = 1 + kZeta[a] * xi(2);
    dN(a, 0) = 0.125 * kXi[a] * fy * fz;
    dN(a, 1) = 0.125 * kEta[a] * fx * fz;
    dN(a, 2) = 0.125 * kZeta[a] * fx * fy;
  }
  return dN;
}

bool hexGradients(const NodeMatrix &X, const Eigen::Vector3d &xi,
                  Eigen::Matrix<double, 8, 3> &dNdX, double &detJ) {
  const Eigen::Matrix<double, 8, 3> dNdxi = hexShapeGradient(xi);
  const Eigen::Matrix3d jac = X.transpose() * dNdxi; // dX_i/dxi_j
  detJ = jac.determinant();
  if (!(detJ > 0.0)) return false;
  dNdX = dNdxi * jac.inverse();
  return true;
}

CornerJacobians cornerJacobians(const NodeMatrix &X, const NodeMatrix &u, double regularity) {
  const NodeMatrix x = X + u;
  std::array<double, 8> reference{}, deformed{};
  double mean = 0.0;
  for (int a = 0; a < 8; ++a) {
    const Eigen::Matrix<double, 8, 3> dNdxi = hexShapeGradient(hexNodeXi(a));
    reference[a] = (X.transpose() * dNdxi).determinant();
    deformed[a] = (x.transpose() * dNdxi).determinant();
    mean += reference[a] / 8.0;
  }
  constexpr double inf = std::numeric_limits<double>::infinity();
  CornerJacobians out{inf, inf};
  for (int a = 0; a < 8; ++a) {
    // det F = det(dx/dxi) / det(dX/dxi) whatever the reference's sign: a zero-strain configuration
    // may turn a near-degenerate corner of the imaged mesh over (its Gauss points stay positive),
    // and det F there is still the ratio; only a reference det of exactly 0 leaves it undefined.
    if (reference[a] == 0.0) continue;
    const double J = deformed[a] / reference[a];
    out.all = std::min(out.all, J);
    if (reference[a] >= regularity * mean) out.regular = std::min(out.regular, J);
  }
  return out;
}

double minCornerJacobian(const NodeMatrix &X, const NodeMatrix &u) { return cornerJacobians(X, u, 0.0).all; }

double minRegularCornerJacobian(const NodeMatrix &X, const NodeMatrix &u, double regularity) {
  return cornerJacobians(X, u, regularity).regular;
}

} // namespace glossa::fem
