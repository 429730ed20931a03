#pragma once
// The deck's mesh file (Mesh/type = file): the file in its format, the nodes Mesh/File/moved nodes
// moves, and the ANSYS extras (element components, fibre polylines, node lists), as one mesh
// with its sets (doc/meshes.md). Refinement and the zero-strain configuration come after, in the
// scene factory.

#include <string>
#include <vector>

#include "io/deck/Deck.hpp"
#include "mesh/HexMesh.hpp"

namespace glossa::input {

// The mesh of a validated deck's Mesh/File, before refinement; what the readers changed on the
// way in goes to `notes`. A file's error is a DeckError naming the parameter that named the file.
mesh::HexMesh readFileMesh(const io::Deck &deck, std::vector<std::string> &notes);

}  // namespace glossa::input
