#pragma once
// The dof layout with the Tpetra objects built on it once: the communicator and the maps that
// the Assembler's vectors, matrices and per-element values are distributed by. DofLayout says
// who owns what without Trilinos; this adds what Tpetra needs of it, in one place, so that a
// user of the Assembler asks for its layout() and not for each map in turn.

#include <cstddef>

#include <Teuchos_RCP.hpp>

#include "assembly/DofLayout.hpp"
#include "assembly/TpetraTypes.hpp"
#include "model/Scene.hpp"

namespace glossa::assembly {

class DistributedLayout : public DofLayout {
public:
  DistributedLayout(DofLayout layout, Teuchos::RCP<const Comm> comm);

  Teuchos::RCP<const Comm> comm() const { return comm_; }
  // The owned dofs: solution and residual vectors, matrix rows.
  Teuchos::RCP<const Map> ownedMap() const { return ownedMap_; }
  // The owned dofs, then the ghosts of the local elements: where element values are gathered.
  Teuchos::RCP<const Map> overlapMap() const { return overlapMap_; }
  // One entry per local element (GID = mesh element id): multipliers and element pressures.
  Teuchos::RCP<const Map> elementMap() const { return elementMap_; }
  std::size_t numLocalElements() const { return localElements.size(); }

private:
  Teuchos::RCP<const Comm> comm_;
  Teuchos::RCP<const Map> ownedMap_, overlapMap_, elementMap_;
};

// Which rank owns which element, node and dof: the deck's partitioner (Zoltan2) or the built-in
// bisection. Collective.
DofLayout distributeScene(const model::Scene &scene, const Teuchos::RCP<const Comm> &comm);

} // namespace glossa::assembly
