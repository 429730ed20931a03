#pragma once
// The deck's "Contact" section: one sublist per contact of a face set of the body with a rigid
// obstacle (plane, sphere, cylinder, or a triangulated surface from an OBJ or STL file), at rest
// or moving, frictionless, with Coulomb friction or tied; with another face set of the body (a
// deformable pair) or with itself (self-contact); declared and parsed into model::RigidContact
// (doc/contact.md, "In decks").

#include <Teuchos_ParameterList.hpp>

#include "io/deck/Deck.hpp"
#include "model/Scene.hpp"

namespace glossa::input {

// The parameters of one contact (the section's template sublist).
Teuchos::ParameterList contactParameters();

// The deck's contacts (validated deck) into scene.contacts, moving obstacles with their time
// functions (`endTime`: the deck's own, a ramp's default duration); a missing face set or master
// face set, a pair of a face set with itself where self-contact was not asked, a zero normal or
// axis, a missing radius, penalty or surface file, and nodes that start inside the obstacle deeper
// than the deck tolerates are DeckErrors naming the parameter (a bad surface file: SurfaceError).
void buildContacts(const io::Deck &deck, const mesh::HexMesh &m, double endTime, model::Scene &scene);

}  // namespace glossa::input
