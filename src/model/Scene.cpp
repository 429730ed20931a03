#include "model/Scene.hpp"

#include "mesh/ReferenceCoordinates.hpp"

namespace glossa::model {

void useReferenceNodes(Scene &scene, std::vector<Eigen::Vector3d> reference) {
  mesh::replaceReferenceNodes(scene.mesh, std::move(reference));
  for (auto &muscle : scene.muscles.external)
    for (std::size_t i = 0; i < muscle.nodes.size(); ++i)
      muscle.fibres[i].insertion = scene.mesh.nodes[muscle.nodes[i]];
}

} // namespace glossa::model
