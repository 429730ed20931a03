#pragma once
// The deck's "Airway" section: the lumen between the tongue's airway face set and a rigid wall
// surface (OBJ or STL), measured in cross-sections along a centreline fixed at rest, declared and
// parsed into model::AirwayOutput (doc/airway.md). Without a face set the section is off.

#include <Teuchos_ParameterList.hpp>

#include "io/deck/Deck.hpp"
#include <memory>

#include "model/AirwayOutput.hpp"
#include "model/Scene.hpp"

namespace glossa::input {

Teuchos::ParameterList airwayParameters();

// The deck's airway (validated deck) over the built scene (its face set, the contact it names);
// the centreline from the imaged positions; null when the section is off. A missing wall file or
// start/end point, an unknown face set or contact, and a centreline the geometry does not give
// are DeckErrors naming the parameter (a bad wall file: SurfaceError).
std::shared_ptr<const model::AirwayOutput> buildAirway(const io::Deck &deck, const model::Scene &scene);

}  // namespace glossa::input
