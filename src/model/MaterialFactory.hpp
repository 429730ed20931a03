#pragma once
// The deck's "Material" section: declares its parameters and builds the isochoric matrix law
// (neo-Hookean or Fung), the fibre families with their direction fields and the muscle groups
// driving them (MuscleArchitecture), the volumetric energy, the density and the element
// formulation.

#include <memory>

#include <Teuchos_ParameterList.hpp>

#include "io/deck/Deck.hpp"
#include "materials/IsochoricMaterial.hpp"
#include "materials/VolumetricEnergy.hpp"
#include "mesh/HexMesh.hpp"
#include "model/MuscleArchitecture.hpp"

namespace glossa::model {

Teuchos::ParameterList materialParameters();

struct BuiltMaterial {
  // The matrix law: the whole material of elements without fibres; its shear modulus scales the
  // augmented-Lagrangian penalty.
  std::shared_ptr<const materials::IsochoricMaterial> isochoric;
  materials::VolumetricEnergy volumetric{materials::VolumetricEnergy::Form::SimoTaylor, 0.0};
  MuscleArchitecture muscles;
  double density = 1060.0;
  bool plainQ1 = false;
  bool symmetricTangent = true; // false for the eq. 5 fibre stress form
};

// `deck` must have been validated. Errors are DeckErrors naming the parameter. Element sets and
// fibre direction fields refer to `mesh`; `endTime` scales default ramps of the neural inputs.
BuiltMaterial buildMaterial(const io::Deck &deck, const mesh::HexMesh &mesh, double endTime);

} // namespace glossa::model
