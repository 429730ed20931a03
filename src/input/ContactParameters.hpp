#pragma once
// The deck's "Contact" section: one sublist per contact of a face set of the body with a rigid
// analytic obstacle (plane, sphere, cylinder), declared and parsed into model::RigidContact
// (doc/contact.md, "In decks").

#include <Teuchos_ParameterList.hpp>

#include "io/deck/Deck.hpp"
#include "model/Scene.hpp"

namespace glossa::input {

// The parameters of one contact (the section's template sublist).
Teuchos::ParameterList contactParameters();

// The deck's contacts (validated deck) into scene.contacts; a missing face set, a zero normal or
// axis, a missing radius or penalty is a DeckError naming the parameter.
void buildContacts(const io::Deck &deck, const mesh::HexMesh &m, model::Scene &scene);

}  // namespace glossa::input
