#include "contact/FrictionLaw.hpp"

namespace glossa::contact {

TangentialTraction coulombTraction(const Eigen::Vector3d &x, const Eigen::Vector3d &anchor, const ClosestPoint &cp,
                                   double tN, double normalPenalty, const FrictionSettings &friction) {
  const Eigen::Vector3d &n = cp.normal;
  const Eigen::Matrix3d &dN = cp.dNormal;
  const Eigen::Vector3d v = x - anchor;
  const double nv = n.dot(v);
  // d(P v)/dx with P = I - n n^T and n = n(x): I - n n^T - (n.v) dN - n (v^T dN).
  const Eigen::Matrix3d dPv =
      Eigen::Matrix3d::Identity() - n * n.transpose() - nv * dN - n * (v.transpose() * dN);
  const double epsT = friction.penalty, mu = friction.coefficient;
  const Eigen::Vector3d trial = -epsT * (v - nv * n);
  const Eigen::Matrix3d dTrial = -epsT * dPv;
  const double size = trial.norm(), limit = mu * tN;
  TangentialTraction out;
  if (size <= limit) {  // stick: the anchor stays
    out.traction = trial;
    out.dTraction = dTrial;
    out.anchor = anchor;
    return out;
  }
  // Slip: the trial direction s kept, the size mu tN; d(s)/dx = (I - s s^T)/|trial| dTrial.
  const Eigen::Vector3d s = trial / size;
  out.traction = limit * s;
  out.dTraction = mu * s * (-normalPenalty * cp.gapGradient().transpose()) +
                  (limit / size) * (Eigen::Matrix3d::Identity() - s * s.transpose()) * dTrial;
  out.anchor = x + out.traction / epsT;
  out.slip = (size - limit) / epsT;
  out.slipping = true;
  return out;
}

TangentialTraction tiedTraction(const Eigen::Vector3d &x, const Eigen::Vector3d &anchor, double penalty) {
  TangentialTraction out;
  out.traction = -penalty * (x - anchor);
  out.dTraction = -penalty * Eigen::Matrix3d::Identity();
  out.anchor = anchor;
  return out;
}

}  // namespace glossa::contact
