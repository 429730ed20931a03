#pragma once
// The deck's "Material" section: declares its parameters and builds the isochoric point law
// (neo-Hookean, Fung, either one reinforced by fibre families), the volumetric energy and the
// element formulation.

#include <memory>

#include <Teuchos_ParameterList.hpp>

#include "io/deck/Deck.hpp"
#include "materials/IsochoricMaterial.hpp"
#include "materials/VolumetricEnergy.hpp"

namespace glossa::model {

Teuchos::ParameterList materialParameters();

struct BuiltMaterial {
  std::shared_ptr<const materials::IsochoricMaterial> isochoric;
  materials::VolumetricEnergy volumetric{materials::VolumetricEnergy::Form::SimoTaylor, 0.0};
  bool plainQ1 = false;
  bool symmetricTangent = true; // false for the eq. 5 fibre stress form
};

// `deck` must have been validated. Errors are DeckErrors naming the parameter.
BuiltMaterial buildMaterial(const io::Deck &deck);

} // namespace glossa::model
