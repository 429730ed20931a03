#pragma once
// The plain parts of a run's checkpoint as JSON (stored as CBOR by io::CheckpointStore, so every
// double comes back bit-identical): where the output files had got, and the muscle history.
// What the Simulation itself keeps (its displacement, multipliers, time, step size, the monitors'
// and the controller's state, the summary so far) it packs beside these (doc/output.md, restart).

#include <nlohmann/json.hpp>

#include "model/MuscleHistory.hpp"
#include "solvers/run/StepRecorder.hpp"

namespace glossa::solvers {

nlohmann::json toJson(const OutputMark &mark);
OutputMark outputMarkFromJson(const nlohmann::json &j);

nlohmann::json toJson(const model::MuscleHistory::Snapshot &history);
model::MuscleHistory::Snapshot muscleSnapshotFromJson(const nlohmann::json &j);

} // namespace glossa::solvers
