#include "model/Scene.hpp"

#include "mesh/ReferenceCoordinates.hpp"

namespace glossa::model {

void useReferenceNodes(Scene &scene, std::vector<Eigen::Vector3d> reference) {
  mesh::replaceReferenceNodes(scene.mesh, std::move(reference));
  for (auto &muscle : scene.muscles.external)
    for (std::size_t i = 0; i < muscle.nodes.size(); ++i)
      muscle.fibres[i].insertion = scene.mesh.nodes[muscle.nodes[i]];
}

std::vector<NodeCoupling> contactCouplings(const Scene &scene) {
  std::vector<NodeCoupling> couplings;
  for (const RigidContact &contact : scene.contacts) {
    if (!contact.pair) continue;
    for (std::size_t i = 0; i < contact.faces.size(); ++i)
      couplings.push_back({contact.faces[i].element, contact::coupledNodes(scene.mesh, contact.faces, *contact.pair, i)});
  }
  return couplings;
}

} // namespace glossa::model
