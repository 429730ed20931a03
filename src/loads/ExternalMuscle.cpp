#include "loads/ExternalMuscle.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace glossa::loads {

ExternalMuscle::ExternalMuscle(materials::HillMuscleFibre fibre, double phiF)
    : fibre_(std::move(fibre)), phiF_(phiF) {
  if (!(phiF > 0.0 && phiF <= 1.0)) throw std::invalid_argument("external muscle: phi_f must lie in (0, 1]");
}

ExternalFibreResponse ExternalMuscle::evaluate(const ExternalFibre &fibre, const Eigen::Vector3d &u,
                                               double alpha, double dt, double lambdaCOld) const {
  const double L0 = (fibre.origin - fibre.insertion).norm();
  if (!(L0 > 0.0) || !std::isfinite(L0))
    throw std::invalid_argument("external muscle: the origin coincides with the insertion point");
  if (!(fibre.area >= 0.0) || !std::isfinite(fibre.area))
    throw std::invalid_argument("external muscle: negative or non-finite tributary area");

  ExternalFibreResponse r;
  const Eigen::Vector3d d = fibre.origin - (fibre.insertion + u);  // L_f n_f (eq. 22)
  r.length = d.norm();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!(r.length > 0.0) || !std::isfinite(r.length)) {
    r.force.setConstant(nan);
    r.dForceDu.setConstant(nan);
    r.hill.status = materials::HillSolveStatus::InvalidInput;
    return r;
  }
  r.n = d / r.length;
  r.lambdaF = r.length / L0;
  r.hill = fibre_.evaluate({r.lambdaF, alpha, dt, lambdaCOld});
  if (!materials::succeeded(r.hill.status)) {
    r.force.setConstant(nan);
    r.dForceDu.setConstant(nan);
    return r;
  }

  // Eq. 23 lumped at the node: f = A phi_f g(lambda_f) n_f with g = lambda_f T_f.
  const double scale = fibre.area * phiF_;
  const double g = r.lambdaF * r.hill.T;
  const double dgdLambda = r.hill.T + r.lambdaF * r.hill.dTdLambdaF;
  r.force = scale * g * r.n;
  // dx = du moves the insertion away from the origin along -n: d lambda_f/du = -n^T / L_f^0 and
  // d n_f/du = -(I - n n^T) / L_f, so
  //   df/du = -A phi_f [ g' / L_f^0 n n^T + g / L_f (I - n n^T) ].
  const Eigen::Matrix3d nn = r.n * r.n.transpose();
  r.dForceDu = -scale * (dgdLambda / L0 * nn + g / r.length * (Eigen::Matrix3d::Identity() - nn));
  return r;
}

Eigen::Vector3d spacingRuleOrigin(const Eigen::Vector3d &PI, double cs, double h, int axis,
                                  const Eigen::Vector3d &centre) {
  if (axis < 0 || axis > 2) throw std::invalid_argument("spacing rule: axis must be 0, 1 or 2");
  if (!std::isfinite(cs) || !std::isfinite(h))
    throw std::invalid_argument("spacing rule: cs and h must be finite");
  Eigen::Vector3d PO = centre + cs * (PI - centre);  // eq. 26, lateral coordinates
  PO(axis) = PI(axis) + h;                           // eq. 26, height above the surface
  return PO;
}

Eigen::Vector4d faceTributaryAreas(const FaceNodes &X) {
  // int N_a dA is the dead-traction force of the unit traction t = e_1, component 1 at node a.
  const FaceForces f = deadTractionForces(X, Eigen::Vector3d::UnitX());
  return Eigen::Vector4d(f(0), f(3), f(6), f(9));
}

std::map<std::int64_t, double> tributaryAreas(const std::vector<FaceNodeIds> &faces,
                                              const std::vector<Eigen::Vector3d> &nodes) {
  std::map<std::int64_t, double> areas;
  for (const FaceNodeIds &face : faces) {
    FaceNodes X;
    for (int a = 0; a < 4; ++a) {
      const std::int64_t id = face[static_cast<std::size_t>(a)];
      if (id < 0 || static_cast<std::size_t>(id) >= nodes.size())
        throw std::invalid_argument("tributary areas: node id out of range");
      X.row(a) = nodes[static_cast<std::size_t>(id)].transpose();
    }
    const Eigen::Vector4d A = faceTributaryAreas(X);
    for (int a = 0; a < 4; ++a) areas[face[static_cast<std::size_t>(a)]] += A(a);
  }
  return areas;
}

}  // namespace glossa::loads
