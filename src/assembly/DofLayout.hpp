#pragma once
// Which rank owns which element, node and degree of freedom, without Trilinos. The mesh is
// replicated on every rank, so every rank computes the same layout without communication:
// elements are partitioned geometrically (mesh/Partition, or given, from Zoltan2), a node belongs to the lowest rank
// among its elements, and nodes are renumbered rank by rank so that every rank owns one
// contiguous range of global dofs (dof = 3 * node + component).

#include <cstdint>
#include <vector>

#include "mesh/HexMesh.hpp"
#include "model/Scene.hpp"

namespace glossa::assembly {

using GlobalIndex = long long; // Tpetra's GlobalOrdinal on Debian 12

struct DofLayout {
  int rank = 0;
  int ranks = 1;
  std::vector<int> elementOwner;          // per mesh element
  std::vector<int> nodeOwner;             // per mesh node
  std::vector<GlobalIndex> nodeNumber;    // mesh node -> global node number (contiguous per rank)
  std::vector<mesh::ElementId> localElements; // elements owned by this rank, increasing id
  std::vector<GlobalIndex> ownedDofs;     // increasing
  std::vector<GlobalIndex> overlapDofs;   // owned first, then the ghosts of local elements and couplings
  std::vector<mesh::NodeId> ownedNodes;   // mesh node ids in global-number order

  GlobalIndex dof(mesh::NodeId node, int component) const { return 3 * nodeNumber[node] + component; }
  GlobalIndex numGlobalDofs() const { return 3 * static_cast<GlobalIndex>(nodeNumber.size()); }
};

// `elementOwner`: the owner of every element (e.g. from Zoltan2); empty: the built-in bisection.
// `couplings`: nodes an element's rank needs besides the element's own (a deformable contact's
// master faces), ghosted there.
DofLayout buildDofLayout(const mesh::HexMesh &mesh, int rank, int ranks, std::vector<int> elementOwner = {},
                         const std::vector<model::NodeCoupling> &couplings = {});

} // namespace glossa::assembly
