#include "mesh/MeshQuality.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace glossa::mesh {

namespace {

// Reference coordinates of the eight nodes (see HexMesh.hpp).
constexpr double kXi[8] = {-1, +1, +1, -1, -1, +1, +1, -1};
constexpr double kEta[8] = {-1, -1, +1, +1, -1, -1, +1, +1};
constexpr double kZeta[8] = {-1, -1, -1, -1, +1, +1, +1, +1};

// dX/dxi of the trilinear map, J_ij = sum_a X_ai dN_a/dxi_j with
// N_a = (1 + xi_a xi)(1 + eta_a eta)(1 + zeta_a zeta) / 8. Kept here rather than taken from
// fem/ so that the mesh layer stays below fem in the dependency order (doc/developing.md).
Eigen::Matrix3d referenceJacobian(const Eigen::Matrix<double, 8, 3> &X, double xi, double eta,
                                  double zeta) {
  Eigen::Matrix<double, 8, 3> dN;
  for (int a = 0; a < 8; ++a) {
    dN(a, 0) = 0.125 * kXi[a] * (1 + kEta[a] * eta) * (1 + kZeta[a] * zeta);
    dN(a, 1) = 0.125 * kEta[a] * (1 + kXi[a] * xi) * (1 + kZeta[a] * zeta);
    dN(a, 2) = 0.125 * kZeta[a] * (1 + kXi[a] * xi) * (1 + kEta[a] * eta);
  }
  return X.transpose() * dN;
}

// det[e1 e2 e3] / (|e1| |e2| |e3|), or 0 if an edge is degenerate.
double normalisedDeterminant(const Eigen::Vector3d &e1, const Eigen::Vector3d &e2,
                             const Eigen::Vector3d &e3) {
  const double lengths2 = e1.squaredNorm() * e2.squaredNorm() * e3.squaredNorm();
  if (!(lengths2 > 0.0)) return 0.0;
  return e1.dot(e2.cross(e3)) / std::sqrt(lengths2);
}

// For each corner, the neighbours along the three edges leaving it, in the right-handed order
// Verdict uses (its J(0,0,0) ... J(0,1,1) blocks): a cube gives det = +1 at every corner.
constexpr int kCornerEdges[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                    {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};

}  // namespace

double elementVolume(const Eigen::Matrix<double, 8, 3> &X) {
  const double g = 1.0 / std::sqrt(3.0);  // 2-point Gauss abscissa, weight 1
  double V = 0.0;
  for (double zeta : {-g, g}) {
    for (double eta : {-g, g}) {
      for (double xi : {-g, g}) V += referenceJacobian(X, xi, eta, zeta).determinant();
    }
  }
  return V;
}

double minGaussPointJacobian(const Eigen::Matrix<double, 8, 3> &X) {
  const double g = 1.0 / std::sqrt(3.0);
  double minimum = std::numeric_limits<double>::infinity();
  for (double zeta : {-g, g}) {
    for (double eta : {-g, g}) {
      for (double xi : {-g, g}) {
        minimum = std::min(minimum, referenceJacobian(X, xi, eta, zeta).determinant());
      }
    }
  }
  return minimum;
}

double meshVolume(const HexMesh &mesh) {
  double V = 0.0;
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    V += elementVolume(mesh.elementCoordinates(static_cast<ElementId>(e)));
  }
  return V;
}

double scaledJacobian(const Eigen::Matrix<double, 8, 3> &X) {
  auto node = [&X](int a) -> Eigen::Vector3d { return X.row(a).transpose(); };

  // Centre: the principal axes (Verdict's calc_hex_efg), i.e. 4 dX/dxi at xi = eta = zeta = 0.
  const Eigen::Vector3d axisXi =
      node(1) + node(2) + node(5) + node(6) - node(0) - node(3) - node(4) - node(7);
  const Eigen::Vector3d axisEta =
      node(2) + node(3) + node(6) + node(7) - node(0) - node(1) - node(4) - node(5);
  const Eigen::Vector3d axisZeta =
      node(4) + node(5) + node(6) + node(7) - node(0) - node(1) - node(2) - node(3);
  double minimum = normalisedDeterminant(axisXi, axisEta, axisZeta);

  for (int a = 0; a < 8; ++a) {
    const Eigen::Vector3d x = node(a);
    minimum = std::min(
        minimum, normalisedDeterminant(node(kCornerEdges[a][0]) - x, node(kCornerEdges[a][1]) - x,
                                       node(kCornerEdges[a][2]) - x));
  }
  return minimum;
}

std::vector<double> scaledJacobians(const HexMesh &mesh) {
  std::vector<double> quality;
  quality.reserve(mesh.numElements());
  for (std::size_t e = 0; e < mesh.numElements(); ++e)
    quality.push_back(scaledJacobian(mesh.elementCoordinates(static_cast<ElementId>(e))));
  return quality;
}

std::pair<double, double> scaledJacobianRange(const HexMesh &mesh) {
  if (mesh.numElements() == 0) {
    throw std::runtime_error("scaledJacobianRange: the mesh has no elements");
  }
  const std::vector<double> quality = scaledJacobians(mesh);
  const auto [lo, hi] = std::minmax_element(quality.begin(), quality.end());
  return {*lo, *hi};
}

}  // namespace glossa::mesh
