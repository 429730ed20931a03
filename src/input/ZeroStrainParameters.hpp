#pragma once
// The deck's "Zero strain" section (glossa zero-strain: method, gravity factor, tolerance,
// maximum iterations), declared and parsed once, and what the command asks of the rest of the
// deck: the mesh as read (the imaged geometry) loaded by gravity alone.

#include <Teuchos_ParameterList.hpp>

#include "io/deck/Deck.hpp"
#include "model/Scene.hpp"

namespace glossa::input {

Teuchos::ParameterList zeroStrainParameters();

enum class ZeroStrainMethod { approximate, inverse };

struct ZeroStrainParameters {
  ZeroStrainMethod method = ZeroStrainMethod::inverse;
  double gravityFactor = 1.2; // approximate: the reversed gravity's multiple of the deck's
  double tolerance = 1e-3;    // inverse: of the mean element edge
  int maximumIterations = 10; // inverse: reference updates
};

// `deck` validated against a schema holding zeroStrainParameters() as "Zero strain".
ZeroStrainParameters parseZeroStrainParameters(const io::Deck &deck);

// `imaged`: the scene built from `deck`. Throws io::DeckError naming the parameter when the deck
// sets a reference coordinates file (the command starts from the mesh as read), has a load other
// than gravity, or has no gravity load.
void requireImagedGeometryUnderGravity(const io::Deck &deck, const model::Scene &imaged);

} // namespace glossa::input
