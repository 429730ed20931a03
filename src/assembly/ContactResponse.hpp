#pragma once
// The contact state at a converged Newton solve, beside the assembly: every contact's faces of
// this rank evaluated at u with the trial multipliers, their gaps and pressures recorded in the
// contact's state (for the Uzawa update and the gap tolerance), and what the output reads from
// them, summed or maximised over the ranks.

#include <vector>

#include "assembly/ResultEvaluator.hpp"
#include "contact/ContactMeasures.hpp"

namespace glossa::assembly {

using contact::ContactMeasures;

// Per scene contact: records the gaps and pressures at u into its state and measures them. A
// deformable pair whose faces moved apart by more than its pairing margin is refused
// (io::DeckError naming the parameter to raise). Collective.
std::vector<ContactMeasures> updateContactStates(const ResultEvaluator &results, const Vector &u);

// Under the augmented Lagrangian, the Uzawa update of every contact whose gap tolerance is not
// met (measures from updateContactStates at the same u); true if any was updated.
bool updateContactMultipliers(const model::Scene &scene, const std::vector<ContactMeasures> &measures);

// The contact pressure [Pa], gap [m] and accumulated slip [m] at every mesh node (on every rank),
// for ParaView: the mean, over the contact faces holding the node, of the recorded values of the
// contact points nearest it (point q of a rigid contact's face is nearest its node q, under both
// rules; a pair's n x n points go to the node of their quadrant); a node on no contact face has
// pressure and slip 0 and, like one that no obstacle is within the search radius of, gap NaN.
// From the states as updateContactStates last recorded them. Collective.
struct ContactNodeFields {
  std::vector<double> pressure, gap, slip;
};
ContactNodeFields contactNodeFields(const ResultEvaluator &results);

} // namespace glossa::assembly
