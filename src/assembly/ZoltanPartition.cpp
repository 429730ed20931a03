#include "assembly/ZoltanPartition.hpp"

#include <stdexcept>

#include <Teuchos_CommHelpers.hpp>
#include <Zoltan2_BasicVectorAdapter.hpp>
#include <Zoltan2_PartitioningProblem.hpp>

namespace glossa::assembly {

std::vector<int> partitionElementsWithZoltan2(const mesh::HexMesh &mesh, const Teuchos::RCP<const Comm> &comm,
                                              const std::string &algorithm) {
  using Types = Zoltan2::BasicUserTypes<double, int, long long>;
  using Adapter = Zoltan2::BasicVectorAdapter<Types>;
  const int ranks = comm->getSize(), rank = comm->getRank();
  const auto ne = static_cast<long long>(mesh.numElements());
  const long long begin = ne * rank / ranks, end = ne * (rank + 1) / ranks;
  std::vector<long long> ids;
  std::vector<double> x, y, z;
  for (long long e = begin; e < end; ++e) {
    const Eigen::Vector3d c = mesh.elementCoordinates(static_cast<mesh::ElementId>(e)).colwise().mean().transpose();
    ids.push_back(e);
    x.push_back(c.x());
    y.push_back(c.y());
    z.push_back(c.z());
  }
  std::vector<int> local(static_cast<std::size_t>(ne), 0), owner(local.size(), 0);
  if (ranks > 1) {
    Adapter adapter(static_cast<int>(ids.size()), ids.data(), x.data(), y.data(), z.data());
    Teuchos::ParameterList parameters;
    parameters.set("algorithm", algorithm);
    parameters.set("num_global_parts", ranks);
    parameters.set("imbalance_tolerance", 1.02);
    Zoltan2::PartitioningProblem<Adapter> problem(&adapter, &parameters, comm);
    problem.solve();
    const auto *parts = problem.getSolution().getPartListView();
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (parts[i] < 0 || parts[i] >= ranks)
        throw std::runtime_error("Zoltan2 returned part " + std::to_string(parts[i]) + " for element " +
                                 std::to_string(ids[i]));
      local[static_cast<std::size_t>(ids[i])] = parts[i];
    }
  }
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), owner.data());
  return owner;
}

} // namespace glossa::assembly
