#include "assembly/NullSpace.hpp"

#include <Eigen/Geometry>

namespace glossa::assembly {

Teuchos::RCP<MultiVector> coordinates(const Assembler &assembler) {
  const DistributedLayout &layout = assembler.layout();
  const mesh::HexMesh &mesh = assembler.scene().mesh;
  Teuchos::Array<GO> nodeIds;
  for (mesh::NodeId n : layout.ownedNodes) nodeIds.push_back(layout.nodeNumber[n]);
  auto nodeMap = Teuchos::rcp(new Map(layout.nodeNumber.size(), nodeIds(), 0, layout.comm()));
  auto X = Teuchos::rcp(new MultiVector(nodeMap, 3));
  for (std::size_t i = 0; i < layout.ownedNodes.size(); ++i)
    for (int c = 0; c < 3; ++c) X->replaceLocalValue(static_cast<LO>(i), c, mesh.nodes[layout.ownedNodes[i]](c));
  return X;
}

Teuchos::RCP<MultiVector> rigidBodyModes(const Assembler &assembler) {
  const DistributedLayout &layout = assembler.layout();
  const mesh::HexMesh &mesh = assembler.scene().mesh;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto &x : mesh.nodes) centre += x;
  centre /= static_cast<double>(mesh.numNodes());
  auto modes = Teuchos::rcp(new MultiVector(layout.ownedMap(), 6));
  for (std::size_t i = 0; i < layout.ownedNodes.size(); ++i) {
    const Eigen::Vector3d x = mesh.nodes[layout.ownedNodes[i]] - centre;
    for (int c = 0; c < 3; ++c) {
      const LO lid = static_cast<LO>(3 * i + c);
      modes->replaceLocalValue(lid, c, 1.0);
      for (int r = 0; r < 3; ++r) {
        const Eigen::Vector3d w = Eigen::Vector3d::Unit(r).cross(x); // rotation about axis r
        modes->replaceLocalValue(lid, 3 + r, w(c));
      }
    }
  }
  return modes;
}

} // namespace glossa::assembly
