#include "fem/HexMass.hpp"

namespace glossa::fem {

bool hexMass(const NodeMatrix &X, double rho, MassLumping lumping, ElementMass &M) {
  M.setZero();
  Eigen::Matrix<double, 8, 8> m = Eigen::Matrix<double, 8, 8>::Zero(); // scalar m_ab
  for (const auto &q : gaussHex2()) {
    Eigen::Matrix<double, 8, 3> dNdX;
    double detJ = 0.0;
    if (!hexGradients(X, q.xi, dNdX, detJ)) return false;
    const Eigen::Matrix<double, 8, 1> N = hexShape(q.xi);
    m.noalias() += (rho * detJ * q.weight) * N * N.transpose();
  }
  if (lumping == MassLumping::lumped) {
    // sum_b N_b = 1, so the row sum is int rho N_a dV: the node's share of the element's mass.
    const Eigen::Matrix<double, 8, 1> rows = m.rowwise().sum();
    m = rows.asDiagonal();
  }
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b)
      for (int i = 0; i < 3; ++i) M(3 * a + i, 3 * b + i) = m(a, b);
  return true;
}

} // namespace glossa::fem
