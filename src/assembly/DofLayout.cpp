#include "assembly/DofLayout.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>

#include "mesh/Partition.hpp"

namespace glossa::assembly {

DofLayout buildDofLayout(const mesh::HexMesh &mesh, int rank, int ranks, std::vector<int> elementOwner,
                         const std::vector<model::NodeCoupling> &couplings) {
  DofLayout L;
  L.rank = rank;
  L.ranks = ranks;
  if (!elementOwner.empty() && elementOwner.size() != mesh.numElements())
    throw std::invalid_argument("buildDofLayout: an owner per element is needed");
  L.elementOwner = elementOwner.empty() ? mesh::partitionElements(mesh, ranks) : std::move(elementOwner);
  L.nodeOwner.assign(mesh.numNodes(), std::numeric_limits<int>::max());
  for (std::size_t e = 0; e < mesh.numElements(); ++e)
    for (mesh::NodeId n : mesh.elements[e]) L.nodeOwner[n] = std::min(L.nodeOwner[n], L.elementOwner[e]);
  // A node no element uses (allowed by Mesh/Checks/unused nodes = fix, which holds it) belongs
  // to rank 0, so that every node has its dofs on some rank.
  for (int &owner : L.nodeOwner)
    if (owner == std::numeric_limits<int>::max()) owner = 0;

  // Renumber nodes rank by rank (stable in mesh id within a rank).
  L.nodeNumber.assign(mesh.numNodes(), -1);
  GlobalIndex next = 0;
  for (int r = 0; r < ranks; ++r)
    for (std::size_t n = 0; n < mesh.numNodes(); ++n)
      if (L.nodeOwner[n] == r) {
        L.nodeNumber[n] = next++;
        if (r == rank) L.ownedNodes.push_back(static_cast<mesh::NodeId>(n));
      }

  for (std::size_t e = 0; e < mesh.numElements(); ++e)
    if (L.elementOwner[e] == rank) L.localElements.push_back(static_cast<mesh::ElementId>(e));

  for (mesh::NodeId n : L.ownedNodes)
    for (int c = 0; c < 3; ++c) L.ownedDofs.push_back(L.dof(n, c));
  std::set<GlobalIndex> ghosts;
  for (mesh::ElementId e : L.localElements)
    for (mesh::NodeId n : mesh.elements[e])
      if (L.nodeOwner[n] != rank)
        for (int c = 0; c < 3; ++c) ghosts.insert(L.dof(n, c));
  for (const model::NodeCoupling &coupling : couplings)
    if (L.elementOwner[coupling.element] == rank)
      for (mesh::NodeId n : coupling.nodes)
        if (L.nodeOwner[n] != rank)
          for (int c = 0; c < 3; ++c) ghosts.insert(L.dof(n, c));
  L.overlapDofs = L.ownedDofs;
  L.overlapDofs.insert(L.overlapDofs.end(), ghosts.begin(), ghosts.end());
  return L;
}

} // namespace glossa::assembly
