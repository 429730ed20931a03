#include "assembly/DistributedLayout.hpp"

#include <utility>

#include "assembly/ZoltanPartition.hpp"

namespace glossa::assembly {

namespace {
Teuchos::RCP<const Map> makeMap(const std::vector<GlobalIndex> &gids, Tpetra::global_size_t total,
                                const Teuchos::RCP<const Comm> &comm) {
  Teuchos::Array<GO> ids(gids.begin(), gids.end());
  return Teuchos::rcp(new Map(total, ids(), 0, comm));
}
} // namespace

DistributedLayout::DistributedLayout(DofLayout layout, Teuchos::RCP<const Comm> comm)
    : DofLayout(std::move(layout)), comm_(std::move(comm)) {
  ownedMap_ = makeMap(ownedDofs, numGlobalDofs(), comm_);
  overlapMap_ = makeMap(overlapDofs, Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), comm_);
  // elementOwner has an entry per mesh element.
  elementMap_ = makeMap(std::vector<GlobalIndex>(localElements.begin(), localElements.end()), elementOwner.size(), comm_);
}

DofLayout distributeScene(const model::Scene &scene, const Teuchos::RCP<const Comm> &comm) {
  std::vector<int> owner;
  if (scene.partitioner != model::Partitioner::coordinateBisection && comm->getSize() > 1)
    owner = partitionElementsWithZoltan2(scene.mesh, comm,
                                         scene.partitioner == model::Partitioner::zoltan2Rcb ? "rcb" : "multijagged");
  return buildDofLayout(scene.mesh, comm->getRank(), comm->getSize(), std::move(owner), model::contactCouplings(scene));
}

} // namespace glossa::assembly
