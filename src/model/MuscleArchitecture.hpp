#pragma once
// Where the fibres are and which muscle drives them (doc/theory.md, §2): the muscle groups with
// their activation dynamics and neural input, and, per element, the fibre families present with
// their reference directions. Elements with the same families share one point law
// (materials::MuscleMaterial), whose families' volume fractions split the total fibre fraction
// equally among the families present (eq. 3, paper §5.2). Passive fibre families are Hill
// fibres whose contractile element never activates (group -1). No Trilinos.

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "materials/ActivationDynamics.hpp"
#include "loads/ExternalMuscle.hpp"
#include "materials/MuscleMaterial.hpp"
#include "mesh/HexMesh.hpp"
#include "model/TimeFunction.hpp"

namespace glossa::model {

struct MuscleGroup {
  std::string name;
  double T0s = 1.0;                            // scales the contractile force, in [0, 1]
  materials::ActivationDynamics activation;    // eq. 24
  TimeFunction input = TimeFunction::constant(); // neural input u(t), clamped to [0, 1]
  double initialActivation = 0.0;              // alpha(0), in [alpha_min, 1]
};

// Elements that carry the same fibre families.
struct FibreRegion {
  std::shared_ptr<const materials::MuscleMaterial> law;
  std::vector<int> familyGroup;   // per family of `law`: its muscle group, -1 for passive fibres
  std::vector<std::string> familyNames;
};

// An external muscle (eq. 22-23): fibres from fixed origins to the nodes of an insertion face
// set, pulling with phi_f lambda_f T_f on each node's tributary area; activated with its group.
struct ExternalMuscleGroup {
  std::string name;
  int group = -1;
  std::shared_ptr<const loads::ExternalMuscle> law;
  std::vector<mesh::NodeId> nodes;          // insertion nodes
  std::vector<loads::ExternalFibre> fibres; // per node: origin, reference insertion, area
};

struct MuscleArchitecture {
  std::vector<MuscleGroup> groups;
  std::vector<FibreRegion> regions;
  std::vector<int> elementRegion;                    // per mesh element; -1: matrix only
  std::vector<materials::FamilyDirections> directions; // per mesh element, one column per family
  // Per mesh element and quadrature point, when a family's directions vary inside elements
  // (polylines sampled at the quadrature points); empty otherwise. `directions` then still holds
  // the direction at the element's centroid, for output and fibre lengths.
  std::vector<std::array<materials::FamilyDirections, 8>> pointDirections;

  std::vector<ExternalMuscleGroup> external;

  bool hasFibres() const { return !regions.empty(); }
  // The per-point directions of mesh element e, or null when they equal directions[e].
  const std::array<materials::FamilyDirections, 8> *pointDirectionsOf(std::size_t e) const {
    return pointDirections.empty() ? nullptr : &pointDirections[e];
  }
  int groupIndex(const std::string &name) const; // -1 if absent
  // Whether mesh element e carries a fibre family of muscle group `group`.
  bool carriesGroup(std::size_t e, int group) const {
    if (elementRegion.empty() || elementRegion[e] < 0) return false;
    const auto &families = regions[static_cast<std::size_t>(elementRegion[e])].familyGroup;
    return std::find(families.begin(), families.end(), group) != families.end();
  }
};

} // namespace glossa::model
