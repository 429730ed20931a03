#pragma once
// One contact's faces of this rank evaluated at a load target's displacement, for the assembly
// (forces and tangent subtracted) and for the state at a converged solve (each point's gap and
// pressure, and friction state): a rigid obstacle's faces through contact/FaceContact, a deformable pair's slave
// faces through the search among their candidate master faces (contact/DeformablePair) and
// contact/PairContact. The one place that gathers a contact's faces.

#include <functional>

#include "assembly/LoadContribution.hpp"

namespace glossa::assembly {

// Receives each evaluated point: the contact face's index (in the contact's `faces`), the point's
// index on it, and its state.
using ContactPointVisitor =
    std::function<void(std::size_t face, std::size_t q, const contact::ContactPointState &)>;

// Evaluates `contact` on this rank's faces at the target's displacement with the state's trial
// multipliers (augmented Lagrangian) or none (penalty), and a rigid obstacle's committed friction
// anchors: subtracts the forces, and with the
// target's K the tangent, if the target has a residual; passes every point to `visit` if given.
// A deformable pair's forces on master nodes of other ranks go to this rank's ghosts of them (the
// layout's couplings), which the export adds to their owners.
void evaluateContact(const LoadTarget &target, const model::RigidContact &contact,
                     const ContactPointVisitor *visit);

// Which node of its face contact point q of contact face `face` lies nearest (the quadrant of its
// (s, t)), for the node fields: q itself for a rigid obstacle's four points.
int nearestFaceNode(const model::RigidContact &contact, std::size_t face, std::size_t q);

}  // namespace glossa::assembly
