#pragma once
// Builds the model::Scene from the deck sections it owns ("Mesh", "Material", "Boundary conditions",
// "Loads", "Contact", "Named points") and declares their parameters. Later checks that need the mesh
// (a set name that does not exist, a named point off the mesh) are DeckErrors naming the path.

#include <Teuchos_ParameterList.hpp>

#include "io/deck/Deck.hpp"
#include "model/Scene.hpp"

namespace glossa::input {

// Declared parameters of the scene's sections, to be merged into the deck schema.
void declareSceneParameters(Teuchos::ParameterList &schema);

// `deck` must have been validated (defaults filled). `endTime` scales default ramps.
model::Scene buildScene(const io::Deck &deck, double endTime);

} // namespace glossa::input
