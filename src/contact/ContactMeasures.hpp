#pragma once
// What one contact amounts to at a converged state, over all ranks: the output's contact area,
// normal and tangential force, penetration and active points, and the largest gap error the Uzawa loop tests
// against the contact's gap tolerance (doc/contact.md). A plain value.

namespace glossa::contact {

struct ContactMeasures {
  double area = 0;               // sum of w_q j_q over the points that carry pressure [m^2]
  double normalForce = 0;        // sum of t_q w_q j_q: the obstacle's push [N]
  // sum of |t_T,q| w_q j_q: the friction force, summed as the normal force is, so that it is
  // mu times the normal force when every point slips [N]
  double tangentialForce = 0;
  double largestPenetration = 0; // largest -g_q over the points that carry pressure [m]
  double largestGapError = 0;    // largest gapError [m]
  long activePoints = 0;         // points with t_q > 0
  double gapTolerance = 0;       // [m]
  bool augmented = false;        // the augmented Lagrangian (a penalty has no gap tolerance to meet)
  bool gapMet() const { return !augmented || largestGapError <= gapTolerance; }
};

} // namespace glossa::contact
