#include "loads/BodyForce.hpp"

#include <stdexcept>
#include <string>

#include "fem/HexShape.hpp"

namespace glossa::loads {

HexForces bodyForces(const HexNodes &X, const Eigen::Vector3d &b) {
  HexForces f = HexForces::Zero();
  for (const auto &q : fem::gaussHex2()) {
    Eigen::Matrix<double, 8, 3> dNdX;
    double detJ = 0.0;
    if (!fem::hexGradients(X, q.xi, dNdX, detJ)) return HexForces::Zero();
    const auto N = fem::hexShape(q.xi);
    for (int a = 0; a < 8; ++a) f.segment<3>(3 * a) += N(a) * detJ * q.weight * b;
  }
  return f;
}

Eigen::Vector3d postureGravity(const std::string &posture, double g) {
  if (posture == "upright") return {0.0, -g, 0.0};
  if (posture == "supine") return {-g, 0.0, 0.0};
  throw std::invalid_argument("unknown posture '" + posture + "' (upright, supine)");
}

} // namespace glossa::loads
