#pragma once
// What the multilevel preconditioners (MueLu, FROSch) need of the problem for elasticity, on the
// Assembler's layout: the nodal coordinates and the six rigid-body modes, the near null space
// their coarse spaces are built to reproduce. They describe the mesh on the layout, not the
// residual, so they sit beside the Assembler rather than in it.

#include <Teuchos_RCP.hpp>

#include "assembly/Assembler.hpp"

namespace glossa::assembly {

// Nodal coordinates: the owned nodes (a map of global node numbers), 3 columns.
Teuchos::RCP<MultiVector> coordinates(const Assembler &assembler);
// The 3 translations and the 3 rotations about the mesh's centroid, on the owned dofs.
Teuchos::RCP<MultiVector> rigidBodyModes(const Assembler &assembler);

} // namespace glossa::assembly
