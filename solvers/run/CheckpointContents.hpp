#pragma once
// The plain parts of a run's checkpoint as JSON (stored as CBOR by io::CheckpointStore, so every
// double comes back bit-identical): where the output files had got, the muscle history and the
// contacts' multipliers.
// What the run's parts keep (the load stepper's states and step size, the monitors' and the
// controller's state, the summary so far) each packs beside these (doc/output.md, restart).

#include <nlohmann/json.hpp>

#include "assembly/TpetraTypes.hpp"
#include "contact/ContactState.hpp"
#include "model/MuscleHistory.hpp"
#include "solvers/run/StepRecorder.hpp"

namespace glossa::solvers {

nlohmann::json toJson(const OutputMark &mark);
OutputMark outputMarkFromJson(const nlohmann::json &j);

nlohmann::json toJson(const model::MuscleHistory::Snapshot &history);
model::MuscleHistory::Snapshot muscleSnapshotFromJson(const nlohmann::json &j);

// A contact's committed multipliers (4 per contact face). The recorded gaps and pressures are not
// kept: every Uzawa update and output reads those of a solve of its own step, so a restored state
// starts as a new one does, with no point known to be near the obstacle.
nlohmann::json toJson(const contact::ContactState::Snapshot &state);
contact::ContactState::Snapshot contactSnapshotFromJson(const nlohmann::json &j);

// A distributed vector's owned values, and back: io::CheckpointError if the count differs
// (another mesh or partition). `what` names it in the message.
std::vector<double> ownedValues(const assembly::Vector &v);
void assignOwnedValues(assembly::Vector &v, const nlohmann::json &values, const char *what);
// Per-local-element values, checked against the count expected.
std::vector<double> elementValues(const nlohmann::json &values, std::size_t expected, const char *what);

} // namespace glossa::solvers
