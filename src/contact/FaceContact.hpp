#pragma once
// Contact of a bilinear quadrilateral face of the body with a rigid obstacle
// (doc/contact.md, "Enforcement"): at each contact point q of the face, at its current position
// x_q = sum_a N_a(q) (X_a + u_a), the obstacle gives the gap g_q and the normal n_q, and the
// contact pressure is
//   t_q = max(0, lambda_q - eps g_q)                 [Pa],
// with eps the penalty [Pa/m] and lambda_q the point's augmented-Lagrangian multiplier (0 for the
// pure penalty method). The external nodal forces are
//   f_a = sum_q w_q t_q N_a(q) n_q j_q,    j_q = |x_,s x x_,t| at q,
// the CURRENT area element: t_q is a Cauchy traction, a force per deformed area, as the follower
// pressure that loads a body onto the obstacle is, so a block pressed by a pressure p on its
// deformed top carries t = p on its deformed bottom whatever its lateral expansion.
// With friction (contact/FrictionLaw) the traction t_q n_q gains a tangential part t_T from the
// point's anchor, and tied contact replaces both by -eps (x_q - a_q) once the point has touched:
//   f_a = sum_q w_q N_a(q) (t_q n_q + t_T,q) j_q.
// With K: the consistent tangent df/du, from the variations of the gap (dg/dx = n^T at a closest
// point), of the normal (the obstacle's dNormal), of the area element and of the active set
// (points with lambda_q - eps g_q < 0 give nothing; at the kink, = 0, the contact side's
// derivative). Not symmetric in general.
//
// Conventions: the face's node order and forces are those of loads::DeadTraction and
// loads::FollowerPressure (external forces: the residual f_int - f_ext takes -f, the global
// tangent -K). Eigen only.

#include <array>
#include <limits>

#include "contact/FrictionLaw.hpp"
#include "contact/Obstacle.hpp"
#include "loads/FollowerPressure.hpp"

namespace glossa::contact {

// Where a face's four contact points sit (both rules have weight 1 at each point):
//  - gauss: the 2x2 Gauss rule, (+-1/sqrt 3, +-1/sqrt 3); the nodal forces of a uniform pressure
//    are the consistent ones, int N_a t da, on any face shape.
//  - nodal: the nodes themselves (2-point Gauss-Lobatto in each direction), so f_a = t_a n_a j_a:
//    one contact point per node, as a node-to-surface scheme has.
enum class ContactQuadrature { gauss, nodal };

// The face-local (s, t) of the four contact points, in the order of a face's multipliers.
const std::array<Eigen::Vector2d, 4> &contactPointCoordinates(ContactQuadrature rule);

struct ContactSettings {
  double penalty = 0;       // eps [Pa/m], > 0
  double searchRadius = 0;  // [m]: the obstacle is looked for this far from each point
  ContactQuadrature rule = ContactQuadrature::gauss;
  FrictionSettings friction;  // frictionless unless set
};

// One contact point's state after an evaluation.
struct ContactPointState {
  // g_q [m]; +infinity when no obstacle lies within the search radius (never active then).
  double gap = 0;
  double pressure = 0;  // t_q [Pa], >= 0
  double area = 0;      // w_q j_q [m^2]: the point's share of the deformed face (output: area, force)
  double tangential = 0; // |t_T| [Pa]
  double slip = 0;       // the plastic slip of the increment from the last converged state [m]
  // The anchor after this evaluation, in the obstacle's own frame (Obstacle::toBody); NaN: none.
  // Coulomb: the return-mapped anchor of a point in contact, the obstacle's closest point of one
  // within the search radius but apart (its slip is then measured from there); tied: where it
  // first touched, kept.
  Eigen::Vector3d anchor = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  bool tied = false;     // held by tied contact: pressure is then t . n, negative in tension
  bool active() const { return tied || pressure > 0; }
};

using FaceMultipliers = std::array<double, 4>;       // lambda_q [Pa]
using FaceContactPoints = std::array<ContactPointState, 4>;
// Per contact point, the committed anchor in the obstacle's own frame; NaN: none.
using FaceAnchors = std::array<Eigen::Vector3d, 4>;

// External nodal forces of the contact of face X + u with the obstacle; with `points`, each
// point's gap, pressure and friction state; with K, df/du. `anchors`: the committed anchors
// (friction, tied; null: none yet).
loads::FaceForces faceContactForces(const Obstacle &obstacle, const loads::FaceNodes &X,
                                    const loads::FaceNodes &u, const FaceMultipliers &lambda,
                                    const ContactSettings &settings, FaceContactPoints *points = nullptr,
                                    loads::FaceTangent *K = nullptr, const FaceAnchors *anchors = nullptr);

// The Uzawa update of one point's multiplier at a converged state: max(0, lambda - eps g), the
// pressure the point carried there (0 if it was not within the search radius).
double updatedMultiplier(double lambda, double penalty, double gap);

// What the outer loop's gap tolerance is tested on at one point: |g| if the point is active,
// else 0 (and 0 for a tied point, which the penalty alone holds). An active point should touch: a penetration (g < 0) and a pressure held across a gap
// (g > 0, a multiplier left from an earlier state) are both errors of the constraint g = 0.
double gapError(const ContactPointState &point);

}  // namespace glossa::contact
