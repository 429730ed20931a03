#pragma once
// The checks a scene passes before anything is assembled (doc/meshes.md), on the whole mesh on every
// rank, so that 1 and N ranks answer alike:
//  - the mesh checks of mesh/MeshChecks.hpp, on the mesh as its file gives it (a zero-strain
//    configuration replacing its coordinates is a computed deformation of it): duplicate
//    elements and corners with a scaled Jacobian <= 0 are refused; unused and coincident nodes are refused unless the deck's
//    Mesh/Checks says otherwise (unused nodes = fix holds them in place, where they carry no
//    stiffness; coincident nodes = allow keeps the parts they would join apart);
//  - every connected part of the mesh is held against each of its six rigid-body motions by the
//    boundary conditions (fixed components or elastic supports) or the external muscles' lines
//    of action; a free part would make the tangent singular.
// Each refusal is an io::DeckError naming the deck section, what was found and how to fix it.

#include "io/deck/Deck.hpp"
#include "model/Scene.hpp"

namespace glossa::input {

// Declares Mesh/Checks (in the Mesh section's parameter list).
void declareMeshCheckParameters(Teuchos::ParameterList &meshSection);

// Runs every check on `scene` as built from `deck`; may add the "unused nodes" condition.
void checkScene(const io::Deck &deck, model::Scene &scene);

} // namespace glossa::input
