#pragma once
// Whether a checkpoint's values are ones this run could have written (glossa run --restart),
// checked before any of them is used: after the part's CRC has shown it is as written, this
// catches a part edited by hand or by a tool, and one written by a run of another mesh or
// partition. The rules are what the run's parts guarantee when they save: a time in [0, end
// time], step sizes finite, positive and within the deck's bounds, counts non-negative, every
// state value finite, the muscle history's activations and inputs in [0, 1] and its contractile
// stretches positive, the contact multipliers non-negative, sizes that fit this rank's share of the mesh, and CSV lengths that the
// files in the output directory still have. No Trilinos here.

#include <cstddef>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

namespace glossa::solvers {

// What this run's state holds on this rank, for the checks.
struct CheckpointShape {
  int step = 0;                                // the checkpoint's, as `latest` names it
  double endTime = 1.0;                        // Time/end time [s]
  double nominalStep = 1.0;                    // Time/step size [s]: the controller never exceeds it
  double minimumStep = 0.0;                    // Time/minimum step size [s]: nor cuts below it
  std::size_t displacements = 0;               // owned displacement values on this rank
  std::size_t elements = 0;                    // elements on this rank
  std::size_t tissues = 0;                     // penalty ratios (one per tissue)
  std::size_t groups = 0;                      // muscle groups
  std::size_t lambdaC = 0;                     // contractile stretches on this rank
  std::vector<std::size_t> externalLambdaC;    // per external muscle
  std::vector<std::size_t> contactPoints;      // per contact: its multipliers (4 per face)
  bool dynamic = false;                        // Time/analysis = dynamic: the inertia's vectors
  std::filesystem::path outputDirectory;       // where the CSV files it records the lengths of are
};

// Rank 0's run part (the scalars, the monitors' and controller's state, the files' lengths, the
// summary): throws io::CheckpointError naming the value and what is allowed (not the file).
void checkRunValues(const nlohmann::json &run, const CheckpointShape &shape);
// A rank's own part (displacement, multipliers, muscle history) of a run part at time `time`:
// throws io::CheckpointError as above.
void checkPartValues(const nlohmann::json &part, double time, const CheckpointShape &shape);

} // namespace glossa::solvers
