#pragma once
// Element ownership from Zoltan2 (Trilinos' partitioning package) for imported, unstructured
// meshes (Mesh/partitioner, doc/meshes.md): the element centroids are partitioned geometrically by Zoltan2's
// multi-jagged or recursive coordinate bisection algorithm. Every rank passes Zoltan2 a
// contiguous block of the (replicated) mesh's elements; the parts come back for those and are
// summed over the ranks, so every rank ends with the same owner of every element. Zoltan2 is
// deterministic for a given rank count. The built-in bisection (mesh/Partition.hpp) remains the
// default for the generated meshes, whose regression traces it made.

#include <string>
#include <vector>

#include "assembly/TpetraTypes.hpp"
#include "mesh/HexMesh.hpp"

namespace glossa::assembly {

// `algorithm`: Zoltan2's name, "multijagged" or "rcb". Collective. Throws std::runtime_error if
// Zoltan2 fails or returns a part outside [0, ranks).
std::vector<int> partitionElementsWithZoltan2(const mesh::HexMesh &mesh, const Teuchos::RCP<const Comm> &comm,
                                              const std::string &algorithm);

} // namespace glossa::assembly
