#pragma once
// Resolving the names a deck gives (element sets, face sets, muscle groups) against the mesh and
// the muscle architecture, with the DeckError a user needs: the parameter's file, line and path,
// and what exists instead. Shared by the material, load and scene builders.

#include <string>
#include <vector>

#include "io/deck/Deck.hpp"
#include "mesh/HexMesh.hpp"
#include "model/MuscleArchitecture.hpp"

namespace glossa::input {

// The string parameter at `path` (sublists, then the parameter's name).
const std::string &deckString(const io::Deck &deck, const std::vector<std::string> &path);

// The element set named at `path` (refused if it has no elements); an empty name means every
// element.
std::vector<mesh::ElementId> elementSetOrAll(const io::Deck &deck, const mesh::HexMesh &m,
                                             const std::vector<std::string> &path);

// The face set named at `path`.
const std::vector<mesh::ElementFace> &faceSetAt(const io::Deck &deck, const mesh::HexMesh &m,
                                                const std::vector<std::string> &path);

// The node set named at `path`.
const std::vector<mesh::NodeId> &nodeSetAt(const io::Deck &deck, const mesh::HexMesh &m,
                                           const std::vector<std::string> &path);

// The index of the muscle group named at `path`; an empty name gives -1 unless `required`.
int muscleGroupAt(const io::Deck &deck, const model::MuscleArchitecture &muscles, const std::vector<std::string> &path,
                  bool required);

} // namespace glossa::input
