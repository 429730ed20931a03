#pragma once
// The deck's "Material" section: declares its parameters and builds the tissues (each an isochoric
// matrix law, neo-Hookean, Fung, Mooney-Rivlin or Yeoh, with its volumetric law and density, on
// its element set), the fibre families with their direction fields and the muscle groups
// driving them (model::MuscleArchitecture) and the element formulation.

#include <memory>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "io/deck/Deck.hpp"
#include "materials/IsochoricMaterial.hpp"
#include "materials/VolumetricEnergy.hpp"
#include "mesh/HexMesh.hpp"
#include "model/MuscleArchitecture.hpp"
#include "model/Tissue.hpp"

namespace glossa::input {

Teuchos::ParameterList materialParameters();

struct BuiltMaterial {
  // tissues[0]: the Material section's own law, that of every element in no Tissues set; then
  // one per Material/Tissues sublist, in deck order.
  std::vector<model::Tissue> tissues;
  std::vector<int> elementTissue; // per mesh element: its index in `tissues`
  model::MuscleArchitecture muscles;
  bool plainQ1 = false;
  bool symmetricTangent = true; // false for the eq. 5 fibre stress form
};

// `deck` must have been validated. Errors are DeckErrors naming the parameter. Element sets and
// fibre direction fields refer to `mesh`; `endTime` scales default ramps of the neural inputs.
BuiltMaterial buildMaterial(const io::Deck &deck, const mesh::HexMesh &mesh, double endTime);

// The material at one point `x` (glossa point), no mesh needed: the Material section's law and
// every fibre family, directed as its field gives at x, as a material of one "element" (index 0).
// A deck with Tissues, External muscles, a family on an element set or a direction field sampled
// from a mesh (polylines, file) is refused with a DeckError naming the parameter.
BuiltMaterial buildPointMaterial(const io::Deck &deck, const Eigen::Vector3d &x, double endTime);

} // namespace glossa::input
