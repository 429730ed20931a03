#pragma once
// The §7.2 block (two muscle groups of Hill fibres) on 3x3x3 cells with a finite kappa: the small
// muscle scene the integration tests assemble directly, without a run.

#include "RunDeck.hpp"
#include "input/SceneFactory.hpp"

namespace glossa::test {

inline model::Scene smallMuscleBlockScene() {
  const auto schema = app::deckSchema();
  auto deck = io::Deck::fromFile(inputPath("paper/s7_2_gradient.xml"));
  deck.applyOverride("Mesh/Box/cells={3,3,3}", schema);
  deck.applyOverride("Material/Poisson's ratio=0.45", schema); // a finite kappa: the scene's own law
  deck.validate(schema);
  return input::buildScene(deck, 1.0);
}

} // namespace glossa::test
