#pragma once
// External muscles (paper §5, eq. 22-23; §7.1, eq. 26): a fibre bundle runs from an origin P^O
// fixed in space and time to an insertion node on the body's surface, current position
// x = X + u. Per insertion node:
//   L_f n_f = P^O - x,  L_f = |P^O - x|,  L_f^0 = |P^O - X|,             (eq. 22)
//   lambda_f = L_f / L_f^0,
//   f = A phi_f lambda_f T_f(lambda_f) n_f,                              (eq. 23, lumped)
// with A the node's reference tributary area on the insertion face set (sum over its faces of
// int N_a dA, tributaryAreas below), phi_f the external fibre fraction and T_f the Hill fibre
// tension (eq. 11-18) evaluated with the node's own contractile-stretch history. The traction of
// eq. 23 is taken per REFERENCE area (a nominal traction on dead areas); doc/loads.md.
//
// Conventions (doc/loads.md):
//  - f is an EXTERNAL force on the insertion node: add it to f_ext; the residual is f_int - f_ext,
//    so the global tangent gets -dForceDu.
//  - dForceDu = df/du is the consistent 3x3 tangent at fixed history lambda_c_old: through
//    lambda_f, n_f and the Hill tangent dT_f/dlambda_f. It is symmetric (the force is central and
//    the area is a reference area), so this load alone does not need GMRES.
//  - History: one lambda_c per insertion node and muscle, committed (lambda_c_old <- lambdaC)
//    only when the step converges; the reference state has lambda_c = 1 (lambda_f = 1).
// Eigen only (with the Eigen-only materials library).

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "loads/DeadTraction.hpp"
#include "materials/HillMuscleFibre.hpp"

namespace glossa::loads {

// One insertion node of an external muscle.
struct ExternalFibre {
  Eigen::Vector3d origin;     // P^O [m], fixed (eq. 22)
  Eigen::Vector3d insertion;  // X, the insertion node's reference position [m]; |P^O - X| > 0
  double area = 0.0;          // A, the node's reference tributary area [m^2], >= 0
};

struct ExternalFibreResponse {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();     // f [N], external
  Eigen::Matrix3d dForceDu = Eigen::Matrix3d::Zero();  // df/du [N/m]
  Eigen::Vector3d n = Eigen::Vector3d::Zero();         // n_f, unit, from x towards P^O
  double length = 0.0;                                 // L_f [m]
  double lambdaF = 1.0;                                // lambda_f = L_f / L_f^0
  // The Hill response at lambda_f: T, dTdLambdaF, lambdaC (to commit), status. If
  // !materials::succeeded(hill.status) (or L_f = 0: InvalidInput), force and dForceDu are NaN:
  // the caller must fail the Newton step (and cut the time step back).
  materials::HillFibreResponse hill;
};

class ExternalMuscle {
 public:
  // phiF: the fibre fraction of the external portion (Table I: 0.7), in (0, 1].
  ExternalMuscle(materials::HillMuscleFibre fibre, double phiF);

  // Force and tangent at displacement u of the insertion node, activation alpha in [0, 1] (shared
  // with the group's internal fibres), time step dt > 0 and the node's committed lambda_c.
  // Throws std::invalid_argument if the fibre has zero reference length or a negative area.
  ExternalFibreResponse evaluate(const ExternalFibre &fibre, const Eigen::Vector3d &u, double alpha,
                                 double dt, double lambdaCOld) const;

  const materials::HillMuscleFibre &fibre() const { return fibre_; }
  double phiF() const { return phiF_; }

 private:
  materials::HillMuscleFibre fibre_;
  double phiF_;
};

// The spacing rule of eq. 26 (§7.1): the origin of the fibre inserting at P^I lies at height h
// above it along `axis` (y in the paper) and its two other coordinates are those of P^I scaled by
// cs about `centre` (the coordinate origin in the paper, the block's symmetry corner):
//   P^O_axis = P^I_axis + h,  P^O_k = c_k + cs (P^I_k - c_k) for k != axis.
// cs = 1 gives fibres normal to the face, cs > 1 fans them out (a larger angle of insertion).
Eigen::Vector3d spacingRuleOrigin(const Eigen::Vector3d &PI, double cs, double h, int axis = 1,
                                  const Eigen::Vector3d &centre = Eigen::Vector3d::Zero());

// int_A N_a dA for the four nodes of one bilinear face in the reference configuration (2x2
// Gauss, as DeadTraction); they sum to the face area.
Eigen::Vector4d faceTributaryAreas(const FaceNodes &X);

// The tributary area of every node of a face set: faces[i] lists the global ids of face i's four
// nodes (in the order of its FaceNodes), nodes[id] their reference coordinates. Returns id -> A.
using FaceNodeIds = std::array<std::int64_t, 4>;
std::map<std::int64_t, double> tributaryAreas(const std::vector<FaceNodeIds> &faces,
                                              const std::vector<Eigen::Vector3d> &nodes);

}  // namespace glossa::loads
