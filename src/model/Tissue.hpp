#pragma once
// A tissue: one matrix law with its volumetric law and density, on a set of elements. The paper's
// §8 model has several in one mesh (bone, cartilage, adipose tissue, the muscular tongue); the
// deck's Material section is the first (the law of every element in no tissue's element set),
// each sublist of Material/Tissues adds one. Fibre families and muscle groups are laid over the
// tissues as before, each fibre region with its element's matrix. No Trilinos.

#include <memory>
#include <string>

#include "materials/IsochoricMaterial.hpp"
#include "materials/VolumetricEnergy.hpp"

namespace glossa::model {

struct Tissue {
  std::string name;                                         // "Material", or the Tissues sublist's
  std::shared_ptr<const materials::IsochoricMaterial> matrix; // its shear modulus scales its penalty
  // The physical volumetric law as the deck gives it (kappa may be +inf); the solver puts the
  // tangent's kappa_t in its place (solvers/run/Simulation).
  materials::VolumetricEnergy volumetric{materials::VolumetricEnergy::Form::SimoTaylor, 0.0};
  double density = 1060.0;                                  // [kg/m^3]
};

} // namespace glossa::model
