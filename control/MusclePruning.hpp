#pragma once
// Muscle pruning (paper §6.1, doc/control.md): only muscle groups in overall tension are searched
// by the GA; contracting a slack group cannot pull the tissue back, so the others keep u = 0.
// A group's state is its length-weighted average fibre stretch
//
//   lambdabar_M = sum_f lambda_f L_f / sum_f L_f
//
// over the fibres f of the group (one contribution per element or per quadrature point and
// family), compared with its value in the reference configuration lambdabar_M^0 (1 at the
// zero-strain state; another value after pre-strain, eq. 1). L_f is the fibre length measure of
// fibreLengthMeasure(): the extent of the element along its reference fibre direction.
//
// The sums are additive, so on several MPI ranks each rank accumulates its own elements and the
// caller sums `weightedStretch` and `length` over ranks (MPI_Allreduce) before average().

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "control/GeneticAlgorithmParameters.hpp"

namespace glossa::control {

// L_f of an element for a fibre with reference direction N: the extent of the element along N,
// max_a N.X_a - min_a N.X_a over its 8 reference nodes X_a (rows), N normalised here. It is the
// length of fibre an element holds (exact for a box aligned with N), unlike volume^(1/3), so a
// group's fine and coarse elements count by how much of the muscle they carry along the fibres.
// Throws std::invalid_argument if N is zero or not finite.
double fibreLengthMeasure(const Eigen::Matrix<double, 8, 3> &X, const Eigen::Vector3d &N);

// Per-group partial sums of lambda_f L_f and L_f.
struct GroupStretchSums {
  std::vector<double> weightedStretch;  // sum lambda_f L_f per group
  std::vector<double> length;           // sum L_f per group

  explicit GroupStretchSums(std::size_t groupCount)
      : weightedStretch(groupCount, 0.0), length(groupCount, 0.0) {}

  std::size_t groupCount() const { return length.size(); }
  // One contribution: fibre stretch lambda_f (> 0) weighted by L_f (>= 0). Group -1 (passive
  // fibres) is ignored. Throws std::invalid_argument for another group out of range or a bad
  // value.
  void add(int group, double stretch, double fibreLength);
  // Adds another set of sums of the same groups (e.g. another rank's, or an external muscle's).
  GroupStretchSums &operator+=(const GroupStretchSums &other);
  // lambdabar_M per group; NaN for a group without fibre length (nothing to judge it by).
  std::vector<double> average() const;
};

// The groups the GA searches, ascending (the genome's gene order): those with
// lambdabar_M > lambdabar_M^0 + tolerance, those marked always evaluated (the genioglossus
// parts), and those whose average or reference is NaN (no fibres seen: pruning removes only
// groups shown to be slack). All vectors are per group. Throws std::invalid_argument on a size
// mismatch or a negative tolerance.
std::vector<int> groupsInTension(const std::vector<double> &averageStretch,
                                 const std::vector<double> &referenceStretch, double tolerance,
                                 const std::vector<bool> &alwaysEvaluated);

// The neural input of every group from a genome over the evaluated groups (others u = 0), and
// back: a previous step's inputs as a seed genome for this step's evaluated groups.
std::vector<double> inputsFromGenome(const std::vector<int> &evaluatedGroups, const Genome &genome,
                                     std::size_t groupCount);
Genome genomeFromInputs(const std::vector<int> &evaluatedGroups, const std::vector<double> &inputs);

}  // namespace glossa::control
