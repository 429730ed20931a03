#pragma once
// The tangential part of the contact law at one contact point (doc/contact.md, "Friction and tied
// contact"): regularised Coulomb friction and tied contact, with the point's anchor, the obstacle's
// point it is elastically held to, as its history.
//
// Coulomb: the trial traction is the tangential penalty eps_T times the tangential offset of the
// point x from its anchor a (the slip since the last converged state, for an anchor left there),
//   t_trial = -eps_T P (x - a),    P = I - n n^T,
// and the return mapping keeps it in the cone |t_T| <= mu t_N: within it the point sticks
// (t_T = t_trial); beyond, it slips (t_T = mu t_N t_trial/|t_trial|) and the anchor follows it to
// x + t_T/eps_T, so the elastic offset is what the cone allows. The plastic slip of the increment
// is (|t_trial| - mu t_N)/eps_T.
// Tied: t = -eps (x - a), every direction, tension allowed.
// Eigen only.

#include <Eigen/Core>

#include "contact/Obstacle.hpp"

namespace glossa::contact {

// How the tangential traction is found. coulomb with coefficient 0 is frictionless.
enum class FrictionLaw { coulomb, tied };

struct FrictionSettings {
  FrictionLaw law = FrictionLaw::coulomb;
  double coefficient = 0;  // mu [-], >= 0 (Coulomb)
  double penalty = 0;      // eps_T [Pa/m], > 0 when mu > 0
  bool frictional() const { return law == FrictionLaw::coulomb && coefficient > 0.0; }
};

struct TangentialTraction {
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();   // t_T [Pa], tangent to the obstacle
  Eigen::Matrix3d dTraction = Eigen::Matrix3d::Zero();  // d t_T / d x at fixed anchor [Pa/m]
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();     // the anchor after the return mapping [m]
  double slip = 0;                                      // plastic slip of the increment [m]
  bool slipping = false;
};

// Coulomb's return mapping at a point x in contact (closest point cp) under the normal pressure
// tN = lambda - eps g >= 0 (eps the normal penalty, so dtN/dx = -eps n^T), from the anchor a.
TangentialTraction coulombTraction(const Eigen::Vector3d &x, const Eigen::Vector3d &anchor, const ClosestPoint &cp,
                                   double tN, double normalPenalty, const FrictionSettings &friction);

// Tied contact's traction -eps (x - a) and its derivative -eps I.
TangentialTraction tiedTraction(const Eigen::Vector3d &x, const Eigen::Vector3d &anchor, double penalty);

}  // namespace glossa::contact
