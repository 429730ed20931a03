#pragma once
// A fibre family at a material point (doc/theory.md, eq. 2-3): a reference unit direction N_f
// (in the zero-strain configuration) and a volume fraction phi_f. The rule of mixtures (eq. 3)
// gives the matrix phi_M = 1 - sum_f phi_f; the paper uses a total fibre fraction of 0.7 split
// equally among the families present at a point (§5.2).

#include <Eigen/Core>
#include <vector>

namespace glossa::materials {

constexpr double kDefaultTotalFibreFraction = 0.7;  // paper §5.2, Table I (phi_f)

struct FibreFamily {
  Eigen::Vector3d N = Eigen::Vector3d::UnitX();  // reference direction, unit length
  double volumeFraction = 0.0;                   // phi_f in [0, 1]
};

// One family per direction (each normalised), totalFraction split equally. Throws on a zero
// direction or totalFraction outside [0, 1].
std::vector<FibreFamily> equalFractionFamilies(const std::vector<Eigen::Vector3d> &directions,
                                               double totalFraction = kDefaultTotalFibreFraction);

// Throws std::invalid_argument unless every N is a unit vector (to 1e-10), every phi_f is in
// [0, 1] and sum phi_f <= 1. Returns the matrix fraction phi_M = 1 - sum phi_f.
double validateFibreFamilies(const std::vector<FibreFamily> &families);

}  // namespace glossa::materials
